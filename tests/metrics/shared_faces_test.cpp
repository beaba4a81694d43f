// Invariants: the faces two meshes share are found exactly (count and correspondence, in
// either orientation), and searching only the reachable part of B gives bit for bit the
// distances of a search against all of B.
#include "metrics/shared_faces.h"

#include "metrics/embree/triangle_scene.h"
#include "metrics/hausdorff_distance.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

namespace holebench {
namespace {

TEST(SharedFaces, AGridSharesEveryFaceWithItsPartButTheRemovedOnes) {
  const Mesh full = build_mesh(test::grid_soup(4));
  const Mesh part = build_mesh(test::grid_without_cells(4, {{1, 1}, {2, 1}}));
  const SharedFaces shared = shared_faces(full, part);
  EXPECT_EQ(shared.count, part.n_faces());
  EXPECT_EQ(shared.count + 4, full.n_faces());  // two cells, two triangles each
  for (auto f : full.faces()) {
    const int match = shared.b_face_of_a[f.idx()];
    if (match < 0)
      continue;
    EXPECT_EQ(shared.a_face_of_b[match], f.idx());
    Point a_centroid(0, 0, 0), b_centroid(0, 0, 0);
    for (auto v : f.vertices())
      a_centroid += full.point(v);
    for (auto v : part.fv_range(part.face_handle(match)))
      b_centroid += part.point(v);
    EXPECT_EQ(a_centroid, b_centroid);
  }
}

TEST(SharedFaces, ReversedOrientationIsShared) {
  TriangleSoup soup = test::grid_soup(2);
  TriangleSoup flipped = soup;
  for (auto& t : flipped.triangles)
    std::swap(t[1], t[2]);
  const SharedFaces shared = shared_faces(build_mesh(soup), build_mesh(flipped));
  EXPECT_EQ(shared.count, soup.triangles.size());
}

TEST(SharedFaces, AMovedVertexUnsharesItsFaces) {
  const Mesh a = build_mesh(test::grid_soup(3));
  Mesh b = a;
  const auto moved = b.vertex_handle(5);
  b.point(moved) += Point(0.0, 0.0, 1e-12);
  std::size_t around = 0;
  for (auto f : b.vf_range(moved)) {
    (void)f;
    ++around;
  }
  ASSERT_GT(around, 0u);
  EXPECT_EQ(shared_faces(a, b).count, a.n_faces() - around);
}

// The reachable part of B: a search against it equals a search against all of B.
TEST(SharedFaces, ReachableFacesGiveTheSameHausdorffDistanceAsAllFaces) {
  const Mesh complete = build_mesh(test::grid_soup(12));
  Mesh repaired = complete;
  for (auto v : repaired.vertices()) {
    const Point p = repaired.point(v);
    if (p[0] > 1.5 && p[0] < 3.5 && p[1] > 1.5 && p[1] < 3.5)
      repaired.point(v)[2] += 0.05 * (p[0] - 1.0);  // a bump: the faces around are unshared
  }
  const SharedFaces shared = shared_faces(repaired, complete);
  ASSERT_GT(shared.count, 0u);
  ASSERT_LT(shared.count, complete.n_faces());
  const auto reach = faces_of_b_within_reach(repaired, complete, shared.b_face_of_a);
  EXPECT_LT(reach.size(), complete.n_faces());
  HausdorffOptions options;
  options.error_bound = 1e-6;
  const embree::TriangleScene all(complete), part(complete, reach);
  const auto with_all = directed_hausdorff(repaired, all, options);
  KnownDistances known;
  known.b_face_of_a = &shared.b_face_of_a;
  const auto with_part = directed_hausdorff(repaired, part, options, known);
  EXPECT_EQ(with_all.lower, with_part.lower);
  EXPECT_EQ(with_all.upper, with_part.upper);
  const auto both = hausdorff_distance(repaired, complete, options);
  EXPECT_EQ(both.a_to_b.lower, with_all.lower);
}

}  // namespace
}  // namespace holebench
