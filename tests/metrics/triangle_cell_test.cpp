// Invariant: a cell's split tiles it (the children's areas sum to the parent's, their corners
// are the parent's corners and edge midpoints) and carries every measured distance to the
// child corner it belongs to; a face's cell has the face's corners and their distances.
#include "metrics/triangle_cell.h"

#include "core/mesh_builder.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

namespace holebench {
namespace {

double area(const std::array<Point, 3>& c) {
  return 0.5 * OpenMesh::cross(c[1] - c[0], c[2] - c[0]).norm();
}

// A scalene triangle with no short decimal coordinates, corners at distinct distances.
TriangleCell scalene_cell() {
  TriangleCell cell;
  cell.corners = {Point(0.1, 0.2, 0.3), Point(1.7, -0.4, 0.5), Point(0.6, 1.3, -0.8)};
  cell.corner_distance = {0.25, 0.5, 0.125};
  cell.corner_face = {4, 7, 9};
  return cell;
}

// What a midpoint query was asked.
struct RecordedQuery {
  Point point;
  double bound = 0.0;
};
// What a midpoint query answers (as embree::ClosestPoint does).
struct FakeClosestPoint {
  double distance = 0.0;
  int face = -1;
};

TEST(TriangleCell, SplitChildrenTileTheParent) {
  const TriangleCell parent = scalene_cell();
  const auto children = split_at_midpoints(parent, [](const Point&, double) {
    return FakeClosestPoint{1.0, 0};
  });
  double sum = 0.0;
  for (const TriangleCell& child : children) {
    sum += area(child.corners);
    EXPECT_NEAR(area(child.corners), area(parent.corners) / 4.0, 1e-14);
  }
  EXPECT_NEAR(sum, area(parent.corners), 1e-14);
}

TEST(TriangleCell, SplitCornersAreTheParentsCornersAndEdgeMidpoints) {
  const TriangleCell parent = scalene_cell();
  const auto& c = parent.corners;
  const Point m01 = (c[0] + c[1]) * 0.5, m12 = (c[1] + c[2]) * 0.5, m20 = (c[2] + c[0]) * 0.5;
  const auto children = split_at_midpoints(parent, [](const Point&, double) {
    return FakeClosestPoint{1.0, 0};
  });
  const std::array<std::array<Point, 3>, 4> expected = {
      {{c[0], m01, m20}, {m01, c[1], m12}, {m20, m12, c[2]}, {m01, m12, m20}}};
  for (int k = 0; k < 4; ++k) {
    for (int i = 0; i < 3; ++i)
      EXPECT_EQ(children[k].corners[i], expected[k][i]) << "child " << k << " corner " << i;
  }
}

TEST(TriangleCell, SplitQueriesEachMidpointWithItsLipschitzBound) {
  const TriangleCell parent = scalene_cell();
  const auto& c = parent.corners;
  const auto& d = parent.corner_distance;
  std::vector<RecordedQuery> seen;
  split_at_midpoints(parent, [&seen](const Point& p, double bound) {
    seen.push_back({p, bound});
    return FakeClosestPoint{1.0, 0};
  });
  ASSERT_EQ(seen.size(), 3u);  // edges c0c1, c1c2, c2c0, in that order
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    EXPECT_EQ(seen[i].point, (c[i] + c[j]) * 0.5);
    EXPECT_EQ(seen[i].bound, std::min(d[i], d[j]) + 0.5 * (c[j] - c[i]).norm());
  }
}

TEST(TriangleCell, SplitCarriesEachDistanceToItsCorner) {
  const TriangleCell parent = scalene_cell();
  int next = 0;
  const auto children = split_at_midpoints(parent, [&next](const Point&, double) {
    const FakeClosestPoint answer{10.0 + next, 100 + next};
    ++next;
    return answer;
  });
  // A corner of a child is either a corner of the parent (its distance and face kept) or
  // the midpoint of edge i (the i-th query's answer).
  const auto& c = parent.corners;
  const std::array<Point, 3> mid = {(c[0] + c[1]) * 0.5, (c[1] + c[2]) * 0.5, (c[2] + c[0]) * 0.5};
  for (const TriangleCell& child : children) {
    for (int k = 0; k < 3; ++k) {
      bool found = false;
      for (int i = 0; i < 3; ++i) {
        if (child.corners[k] == c[i]) {
          EXPECT_EQ(child.corner_distance[k], parent.corner_distance[i]);
          EXPECT_EQ(child.corner_face[k], parent.corner_face[i]);
          found = true;
        } else if (child.corners[k] == mid[i]) {
          EXPECT_EQ(child.corner_distance[k], 10.0 + i);
          EXPECT_EQ(child.corner_face[k], 100 + i);
          found = true;
        }
      }
      EXPECT_TRUE(found);
    }
  }
}

TEST(TriangleCell, FaceCellHasTheFacesCornersInVertexOrderWithTheirDistances) {
  const Mesh mesh = build_mesh(test::tetrahedron_soup());
  VertexDistances vertices;
  for (auto v : mesh.vertices()) {
    vertices.distance.push_back(0.5 + v.idx());
    vertices.nearest_face.push_back(20 + v.idx());
  }
  for (auto f : mesh.faces()) {
    const TriangleCell cell = face_cell(mesh, f, vertices);
    int k = 0;
    for (auto v : f.vertices()) {
      EXPECT_EQ(cell.corners[k], mesh.point(v));
      EXPECT_EQ(cell.corner_distance[k], 0.5 + v.idx());
      EXPECT_EQ(cell.corner_face[k], 20 + v.idx());
      ++k;
    }
    EXPECT_EQ(k, 3);
  }
}

}  // namespace
}  // namespace holebench
