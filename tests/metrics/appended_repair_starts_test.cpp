// Where the whole model's searches of a repair that appends to the input start, from the
// case's first passes (AppendedRepairStarts), against the definitions computed from the
// meshes: every vertex's distance and nearest face as vertex_distances() gives them, the
// faces not on the other surface, the area summed face by face; on a fan closing (new faces
// off the complete model), an exact closing appended to the input (new faces on it, new
// vertices on it) and a repair that does not append (nothing), with and without noise.
#include "metrics/appended_repair_starts.h"

#include "core/boundary_loops.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/triangle_cell.h"
#include "metrics/triangle_geometry.h"

#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <array>
#include <map>
#include <string>
#include <vector>

namespace holebench {
namespace {

struct Reference {
  VertexDistances vertices;
  std::vector<int> unshared_faces;
  double area = 0.0;
};

// The start from A's every face and vertex, as the searches make it without one.
Reference reference(const Mesh& a, const embree::TriangleScene& b_scene,
                    const std::vector<int>& b_face_of_a) {
  Reference r;
  r.vertices = vertex_distances(a, b_scene, &b_face_of_a);
  for (auto f : a.faces()) {
    const double area = triangle_area(face_cell(a, f, r.vertices).corners);
    if (area > 0.0)
      r.area += area;
    if (b_face_of_a[f.idx()] < 0)
      r.unshared_faces.push_back(f.idx());
  }
  return r;
}

void expect_start(const SearchStart& start, const Reference& r, const std::string& what) {
  EXPECT_EQ(start.vertices.distance, r.vertices.distance) << what;
  EXPECT_EQ(start.vertices.nearest_face, r.vertices.nearest_face) << what;
  EXPECT_EQ(start.unshared_faces, r.unshared_faces) << what;
  EXPECT_EQ(start.area, r.area) << what;
}

TEST(AppendedRepairStarts, EqualTheStartsFromTheMeshes) {
  for (const char* id : {"box/corner", "brep/weak/multiple-inner-boundaries/small"}) {
    for (double noise : {0.0, 25.0}) {
      const Case c = generators::make_case(id, 0, noise);
      const embree::TriangleScene complete_scene(c.complete);
      const SharedFacesOfInput shared_of_input(c.input, c.complete);
      const AppendedRepairStarts starts(c.input, c.complete,
                                        first_pass(c.input, c.complete, complete_scene),
                                        shared_of_input.of_input());
      const std::string what = std::string(id) + " noise " + std::to_string(noise);
      int repairs_with_shared_new_faces = 0;
      for (const Mesh& repaired : {test::fan_closing(c.input), test::exact_appended_closing(c)}) {
        const KeptFaces kept = kept_faces(c.input, repaired);
        ASSERT_TRUE(kept.appends_to_input()) << what;
        const SharedFaces shared = shared_faces(repaired, c.complete);
        for (std::size_t f = c.input.n_faces(); f < repaired.n_faces(); ++f)
          repairs_with_shared_new_faces += shared.b_face_of_a[f] >= 0;
        const embree::TriangleScene repaired_scene(repaired);
        const auto to_complete =
            starts.repaired_to_complete(repaired, kept, shared, complete_scene);
        ASSERT_TRUE(to_complete) << what;
        expect_start(*to_complete, reference(repaired, complete_scene, shared.b_face_of_a),
                     what + " repaired to complete");
        const auto from_complete =
            starts.complete_to_repaired(c.complete, repaired, kept, shared, repaired_scene, {});
        ASSERT_TRUE(from_complete) << what;
        expect_start(*from_complete, reference(c.complete, repaired_scene, shared.a_face_of_b),
                     what + " complete to repaired");
      }
      EXPECT_GT(repairs_with_shared_new_faces, 0) << what << ": the exact closing's faces";
    }
  }
}

TEST(AppendedRepairStarts, NoneForARepairThatDoesNotAppend) {
  const Case c = generators::make_case("box/corner");
  const embree::TriangleScene complete_scene(c.complete);
  const SharedFacesOfInput shared_of_input(c.input, c.complete);
  const AppendedRepairStarts starts(c.input, c.complete,
                                    first_pass(c.input, c.complete, complete_scene),
                                    shared_of_input.of_input());
  // The complete model itself: the input's faces, but not at their indices.
  const KeptFaces kept = kept_faces(c.input, c.complete);
  ASSERT_FALSE(kept.appends_to_input());
  const SharedFaces shared = shared_faces(c.complete, c.complete);
  EXPECT_FALSE(starts.repaired_to_complete(c.complete, kept, shared, complete_scene));
  EXPECT_FALSE(
      starts.complete_to_repaired(c.complete, c.complete, kept, shared, complete_scene, {}));
}

}  // namespace
}  // namespace holebench
