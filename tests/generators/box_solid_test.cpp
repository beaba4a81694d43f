#include "generators/box_solid.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench::generators {
namespace {

TEST(BoxSolid, ClosedOutwardAndSixRegions) {
  const BoxOptions options{Point(2.0, 1.5, 1.0), 0.25};
  const Mesh box = make_box(options);
  EXPECT_TRUE(find_boundary_loops(box).empty());
  // Euler characteristic of a sphere.
  EXPECT_EQ(static_cast<int>(box.n_vertices()) - static_cast<int>(box.n_edges()) +
                static_cast<int>(box.n_faces()),
            2);
  EXPECT_EQ(region_count(box), 6);
  // Faces per region: 2 triangles per grid cell.
  EXPECT_EQ(box.n_faces(), 2u * 2 * (8 * 6 + 6 * 4 + 8 * 4));
  // Outward: each face normal points away from the box centre, and along its region's axis.
  const Point centre(1.0, 0.75, 0.5);
  for (auto f : box.faces()) {
    const Point n = face_normal(box, f);
    EXPECT_GT(OpenMesh::dot(n, face_centroid(box, f) - centre), 0.0);
    const int axis = region(box, f) / 2;
    const double sign = region(box, f) % 2 == 0 ? -1.0 : 1.0;
    EXPECT_DOUBLE_EQ(n[axis], sign);
    EXPECT_EQ(provenance(box, f), Provenance::Original);
  }
  // Surface area 2(ab + bc + ca).
  double area = 0.0;
  for (auto f : box.faces())
    area += face_area(box, f);
  EXPECT_NEAR(area, 2.0 * (3.0 + 1.5 + 2.0), 1e-12);
}

TEST(BoxSolid, SameOptionsGiveTheSameMeshBitForBit) {
  const Mesh a = make_box();
  const Mesh b = make_box();
  ASSERT_EQ(a.n_vertices(), b.n_vertices());
  for (auto v : a.vertices())
    EXPECT_EQ(a.point(v), b.point(b.vertex_handle(v.idx())));
}

}  // namespace
}  // namespace holebench::generators
