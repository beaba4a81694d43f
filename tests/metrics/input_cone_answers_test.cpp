// The normal cones at the complete model's samples against the input plus a patch, from the
// case's answers against the input (InputConeAnswers), against normal_cone_angle() asked of a
// scene of the whole repair: every field bit for bit, on a fan closing and an exact closing
// appended to the input, with and without noise, and the input alone.
#include "metrics/input_cone_answers.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "metrics/embree/triangle_scene.h"

#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace holebench {
namespace {

void expect_same_cone(const NormalConeAngle& a, const NormalConeAngle& b, const std::string& what) {
  EXPECT_EQ(a.nearest_distance, b.nearest_distance) << what;
  EXPECT_EQ(a.largest_abs_cosine, b.largest_abs_cosine) << what;
  EXPECT_EQ(a.smallest_deg, b.smallest_deg) << what;
  EXPECT_EQ(a.cone_faces, b.cone_faces) << what;
}

std::vector<int> faces_after(const Mesh& input, const Mesh& repaired) {
  std::vector<int> added;
  for (std::size_t f = input.n_faces(); f < repaired.n_faces(); ++f)
    added.push_back(static_cast<int>(f));
  return added;
}

TEST(InputConeAnswers, APatchAddedToTheInputsAnswersIsTheWholeRepairsCone) {
  for (const std::string id : {"box/corner", "brep/k3/inner/convex-convex-convex/small"}) {
    for (double noise : {0.0, 25.0}) {
      const Case c = generators::make_case(id, 0, noise);
      const std::string what = id + " noise " + std::to_string(noise);
      const embree::TriangleScene input_scene(c.input);
      NormalConeOptions options;
      options.tolerance = 1e-3 * bounding_box_diagonal(c.complete);
      const AreaSamples samples = area_samples(c.complete, 3000);
      const InputConeAnswers answers(samples, input_scene, options);
      ASSERT_EQ(answers.points(), samples.points);

      // The input alone.
      const SampledAnswers alone = answers.with_patch(nullptr);
      ASSERT_EQ(alone.cones.size(), samples.points.size());
      for (std::size_t i = 0; i < samples.points.size(); ++i)
        expect_same_cone(
            alone.cones[i],
            normal_cone_angle(input_scene, samples.points[i], samples.normals[i], options),
            what + " input alone");

      for (const Mesh& repaired : {test::fan_closing(c.input), test::exact_appended_closing(c)}) {
        ASSERT_GT(repaired.n_faces(), c.input.n_faces());
        const embree::TriangleScene patch(repaired, faces_after(c.input, repaired));
        const embree::TriangleScene whole(repaired);
        const SampledAnswers with_patch = answers.with_patch(&patch);
        ASSERT_EQ(with_patch.points, samples.points);
        ASSERT_EQ(with_patch.normals, samples.normals);
        std::size_t changed_by_patch = 0;
        for (std::size_t i = 0; i < samples.points.size(); ++i) {
          const NormalConeAngle expected =
              normal_cone_angle(whole, samples.points[i], samples.normals[i], options);
          expect_same_cone(with_patch.cones[i], expected, what);
          changed_by_patch += expected.nearest_distance != alone.cones[i].nearest_distance ||
                                      expected.cone_faces != alone.cones[i].cone_faces
                                  ? 1
                                  : 0;
        }
        // The patch changes the answers near the hole: the check covers that path.
        EXPECT_GT(changed_by_patch, 0u) << what;
      }
    }
  }
}

}  // namespace
}  // namespace holebench
