// Invariants of the first pass (vertex_distances.h): every vertex's distance is the scene's
// closest point, zero on a face shared with B; every face not lying on B has its cell
// centroid's closest point, the same answer an unbounded query gives, and the faces lying on
// B have none.
#include "metrics/vertex_distances.h"

#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/triangle_cell.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench {
namespace {

TEST(FirstPass, VertexAndCentroidAnswersAreTheScenesClosestPoints) {
  for (const double noise : {0.0, 25.0}) {
    const Case c = generators::make_case("brep/k3/inner/convex-convex-convex/small", 0, noise);
    const embree::TriangleScene complete_scene(c.complete);
    const FirstPass pass = first_pass(c.input, c.complete, complete_scene);
    const std::string what = "noise " + std::to_string(noise);
    ASSERT_EQ(pass.centroid.size(), c.input.n_faces()) << what;
    std::size_t unshared = 0;
    for (auto f : c.input.faces()) {
      const embree::ClosestPoint& answer = pass.centroid[f.idx()];
      if (pass.b_face_of_a[f.idx()] >= 0) {
        EXPECT_EQ(answer.face, -1) << what;
        for (auto v : c.input.fv_range(f))
          EXPECT_EQ(pass.vertices.distance[v.idx()], 0.0) << what;
        continue;
      }
      ++unshared;
      // Summed as the tables sum it (cell_centroid), without the helper: the same bits.
      const auto& corners = face_cell(c.input, f, pass.vertices).corners;
      const Point centroid = (corners[0] + corners[1] + corners[2]) / 3.0;
      const embree::ClosestPoint direct = complete_scene.closest_point(centroid);
      EXPECT_EQ(answer.face, direct.face) << what << " face " << f.idx();
      EXPECT_EQ(answer.distance, direct.distance) << what << " face " << f.idx();
    }
    // Noise moves every input vertex off the complete model: no face lies on it.
    if (noise > 0.0)
      EXPECT_EQ(unshared, c.input.n_faces());
    else
      EXPECT_LT(unshared, c.input.n_faces());
    for (auto v : c.input.vertices()) {
      if (pass.vertices.distance[v.idx()] == 0.0 && noise == 0.0)
        continue;
      EXPECT_EQ(pass.vertices.distance[v.idx()],
                complete_scene.closest_point(c.input.point(v)).distance)
          << what << " vertex " << v.idx();
    }
  }
}

}  // namespace
}  // namespace holebench
