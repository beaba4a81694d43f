#include "generators/hole_punch.h"

#include "core/boundary_loops.h"
#include "generators/box_solid.h"

#include <gtest/gtest.h>

namespace holebench::generators {
namespace {

TEST(HolePunch, RemovesTheFacesAndLeavesOneLoop) {
  const Mesh box = make_box();
  const auto faces = faces_in_ball(box, Point(1.0, 0.75, 1.0), 0.3);
  ASSERT_FALSE(faces.empty());
  const PunchResult punched = punch_faces(box, faces);
  EXPECT_EQ(punched.holed.n_faces() + punched.removed_faces.size(), box.n_faces());
  EXPECT_EQ(find_boundary_loops(punched.holed).size(), 1u);
  // The holed mesh keeps positions: each vertex maps to the same point of the complete one.
  for (auto v : punched.holed.vertices()) {
    const auto original = box.vertex_handle(punched.vertex_to_complete[v.idx()]);
    EXPECT_EQ(punched.holed.point(v), box.point(original));
  }
  for (auto f : punched.holed.faces())
    EXPECT_NE(region(punched.holed, f), kNoRegion);
}

TEST(HolePunch, TwoFacesTouchingAtAVertexAreGrownToAManifoldHole) {
  const Mesh box = make_box();
  // Two faces of the +z region that share exactly one vertex (a checkerboard pattern)
  // would leave a non-manifold vertex; the punch grows the hole instead.
  const auto ball = faces_in_ball(box, Point(1.0, 0.75, 1.0), 0.3);
  std::vector<int> two;
  for (int a : ball) {
    for (int b : ball) {
      int shared = 0;
      for (auto va : box.fv_range(box.face_handle(a))) {
        for (auto vb : box.fv_range(box.face_handle(b)))
          shared += va == vb ? 1 : 0;
      }
      if (a < b && shared == 1 && two.empty())
        two = {a, b};
    }
  }
  ASSERT_EQ(two.size(), 2u);
  const PunchResult punched = punch_faces(box, two);
  EXPECT_GT(punched.removed_faces.size(), 2u);
  for (const auto& loop : find_boundary_loops(punched.holed))
    EXPECT_GE(loop.size(), 3u);
}

}  // namespace
}  // namespace holebench::generators
