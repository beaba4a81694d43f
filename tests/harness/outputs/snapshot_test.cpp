#include "harness/outputs/render/snapshot.h"

#include "core/geometry.h"
#include "generators/box_solid.h"

#include <gtest/gtest.h>

namespace holebench::render {
namespace {

// The pixel at the image's centre.
std::array<int, 3> centre(const Image& image) {
  const std::size_t i =
      (static_cast<std::size_t>(image.height / 2) * image.width + image.width / 2) * 3;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2]};
}

bool blue(const std::array<int, 3>& rgb) {
  return rgb[2] > 2 * rgb[0] && rgb[2] > 2 * rgb[1];
}

// The arrow solid is a closed, consistently oriented surface (build_mesh accepts it).
TEST(Snapshot, ArrowSolidIsClosed) {
  const Mesh arrow = build_mesh(arrow_solid(Point(0, 0, 0), Point(1, 2, 3), 0.05));
  for (auto h : arrow.halfedges())
    EXPECT_FALSE(arrow.is_boundary(h));
}

// A 3D arrow hides the model behind it and is hidden by the model in front of it.
TEST(Snapshot, ArrowsAreDepthTestedAgainstTheModel) {
  const Mesh box = generators::make_box();
  const BoundingBox bounds = bounding_box(box);
  const Point centre_point = bounds.center();
  Camera camera;
  camera.target = centre_point;
  camera.direction = Point(0, 0, -1);
  camera.distance = 5.0 * bounds.diagonal();
  SnapshotOptions options;
  options.width = 64;
  options.height = 48;
  const double radius = 0.05 * bounds.diagonal();
  // Along the view axis through the centre: in front of the box (above its top), then
  // below it.
  const Point top(centre_point[0], centre_point[1], bounds.max[2]);
  const Point bottom(centre_point[0], centre_point[1], bounds.min[2]);
  Overlay in_front;
  in_front.solids.push_back(
      {arrow_solid(top + Point(0, 0, 1.0), top + Point(0, 0, 0.1), radius), {0.05f, 0.15f, 0.75f}});
  EXPECT_TRUE(blue(centre(render_snapshot(box, camera, options, in_front))));
  Overlay behind;
  behind.solids.push_back(
      {arrow_solid(bottom - Point(0, 0, 0.1), bottom - Point(0, 0, 1.0), radius),
       {0.05f, 0.15f, 0.75f}});
  EXPECT_FALSE(blue(centre(render_snapshot(box, camera, options, behind))));
  EXPECT_FALSE(blue(centre(render_snapshot(box, camera, options))));
}

}  // namespace
}  // namespace holebench::render
