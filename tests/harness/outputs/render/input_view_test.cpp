#include "harness/outputs/render/input_view.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "harness/outputs/render/case_view.h"
#include "harness/outputs/render/close_up.h"
#include "metrics/embree/triangle_scene.h"
#include "tests/metrics/test_repairs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace holebench::render {
namespace {

/// The fan closing with its faces marked new (the patch colour).
Mesh marked_fan_closing(const Mesh& input) {
  Mesh repaired = test::fan_closing(input);
  for (std::size_t f = input.n_faces(); f < repaired.n_faces(); ++f)
    repaired.data(repaired.face_handle(static_cast<int>(f))).provenance = Provenance::New;
  return repaired;
}

std::vector<int> faces_after(const Mesh& input, const Mesh& repaired) {
  std::vector<int> added;
  for (std::size_t f = input.n_faces(); f < repaired.n_faces(); ++f)
    added.push_back(static_cast<int>(f));
  return added;
}

/// An arrow into the hole and a line across it: the overlay's solids and lines.
Overlay overlay_at_hole(const Case& c) {
  Overlay overlay;
  const BoundingBox box = bounding_box(c.complete);
  const Point centre = box.center();
  Point target = centre;
  if (!c.holes.empty() && !c.holes.front().removed_faces.empty())
    target = face_centroid(c.complete, c.complete.face_handle(c.holes.front().removed_faces[0]));
  overlay.solids.push_back(
      {arrow_solid(target + (centre - target) * 0.3, target, 0.01 * box.diagonal()), {0, 0, 1}});
  overlay.lines.push_back({target, centre, {1, 0, 1}, 3.0f});
  return overlay;
}

// A repair that appends to its input, drawn over the input's view, is the picture of the
// whole repaired mesh, byte for byte and depth for depth: from the hole's camera and the
// whole model's, with the overlay's solids and lines, on a box, a B-Rep case and a noisy CAD
// model, for an exact closing (new faces on the complete model, sewn to the input) and a fan.
TEST(InputView, APatchDrawnOverTheInputsViewIsTheWholeRepairsPicture) {
  SnapshotOptions options;
  options.width = 120;
  options.height = 90;
  for (const std::string id :
       {"box/corner", "brep/k2/inner/convex/large", "cad/fandisk/edge_convex/small"}) {
    const Case c = generators::make_case(id, 0, id.rfind("cad/", 0) == 0 ? 5.0 : 0.0);
    const embree::TriangleScene input_scene(c.input);
    const Overlay overlay = overlay_at_hole(c);
    std::size_t exact_ties = 0;
    for (const Camera& camera : {hole_camera(c), whole_model_camera(c, Point(-1, -1, -1))}) {
      const InputView view = input_view(c.input, input_scene, camera, options);
      const Rendering input_alone = render_with_depth(c.input, camera, options);
      EXPECT_TRUE(view.picture.image.pixels == input_alone.image.pixels) << id;
      EXPECT_TRUE(view.picture.depth == input_alone.depth) << id;
      const std::vector<Mesh> repairs = {test::exact_appended_closing(c),
                                         marked_fan_closing(c.input)};
      for (const Mesh& repaired : repairs) {
        ASSERT_GT(repaired.n_faces(), c.input.n_faces()) << id;
        const std::vector<int> added = faces_after(c.input, repaired);
        const embree::TriangleScene added_scene(repaired, added);
        const Rendering over =
            render_over_input_view(view, repaired, added, &added_scene, options, overlay);
        const Rendering whole = render_with_depth(repaired, camera, options, overlay);
        EXPECT_TRUE(over.depth == whole.depth) << id;
        // Every pixel is the whole mesh's but where a sample's ray meets two faces at the same
        // distance (a fan across several faces of the model overlaps itself and the input):
        // there either may show, as the scenes' layouts have it.
        const embree::TriangleScene whole_scene(repaired);
        const PrimaryRays rays = primary_rays(camera, options);
        const std::size_t per_pixel = rays.directions.size() / (options.width * options.height);
        for (std::size_t pixel = 0; 3 * pixel < over.image.pixels.size(); ++pixel) {
          if (std::equal(over.image.pixels.begin() + 3 * pixel,
                         over.image.pixels.begin() + 3 * pixel + 3,
                         whole.image.pixels.begin() + 3 * pixel))
            continue;
          const auto first = rays.directions.begin() + pixel * per_pixel;
          const std::vector<Point> directions(first, first + per_pixel);
          std::vector<embree::RayHit> input_hits, added_hits, whole_hits;
          input_scene.intersect_coherent(rays.eye, directions, input_hits);
          added_scene.intersect_coherent(rays.eye, directions, added_hits);
          whole_scene.intersect_coherent(rays.eye, directions, whole_hits);
          bool tie = false;
          for (std::size_t s = 0; s < per_pixel; ++s) {
            const bool added_wins =
                added_hits[s].hit &&
                (!input_hits[s].hit || added_hits[s].distance < input_hits[s].distance);
            const embree::RayHit& ours = added_wins ? added_hits[s] : input_hits[s];
            tie = tie || (ours.hit && whole_hits[s].hit && ours.face != whole_hits[s].face &&
                          ours.distance == whole_hits[s].distance);
          }
          EXPECT_TRUE(tie) << id << ": pixel " << pixel << " differs without a tie";
          exact_ties += &repaired == &repairs.front() ? 1 : 0;
        }
        // The patch shows: the picture is not the input's.
        EXPECT_FALSE(over.image.pixels ==
                     render_with_depth(c.input, camera, options, overlay).image.pixels)
            << id;
      }
      // Nothing added: the input's picture with the overlay.
      const Rendering nothing =
          render_over_input_view(view, c.input, {}, nullptr, options, overlay);
      EXPECT_TRUE(nothing.image.pixels ==
                  render_with_depth(c.input, camera, options, overlay).image.pixels)
          << id;
    }
    // The exact closing overlaps nothing: its pictures are the whole mesh's, byte for byte.
    EXPECT_EQ(exact_ties, 0u) << id;
  }
}

TEST(InputView, OptionsOfAnotherSizeAreRefused) {
  const Case c = generators::make_case("box/corner");
  const embree::TriangleScene scene(c.input);
  SnapshotOptions options;
  options.width = options.height = 32;
  const InputView view = input_view(c.input, scene, hole_camera(c), options);
  options.samples_per_axis = 3;
  EXPECT_THROW(render_over_input_view(view, c.input, {}, nullptr, options), std::invalid_argument);
}

}  // namespace
}  // namespace holebench::render
