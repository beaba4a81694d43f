// What every ray-cast picture shares (snapshot.h's renderer and the case's views kept for its
// jobs, input_view.h): the camera's frame and its primary rays, the shading of what a sample
// sees, the overlay's solids as a scene, and the overlay's lines and dots drawn over a
// depth buffer.
#pragma once

#include "harness/outputs/render/image.h"
#include "harness/outputs/render/snapshot.h"
#include "metrics/embree/triangle_scene.h"

#include <memory>
#include <vector>

namespace holebench::render {

/// The camera's frame and projection for a picture of `width` x `height`.
struct View {
  Point eye, forward, right, up;
  double half_width = 0.0, half_height = 0.0;
  int width = 0, height = 0;

  View(const Camera& camera, int w, int h);

  /// The (not unit) direction of the ray through pixel coordinates (x, y).
  Point ray(double x, double y) const;

  /// Pixel coordinates and distance from the eye of `p`; false behind the camera.
  bool project(const Point& p, double& x, double& y, double& depth) const;
};

/// The directions of row `y`'s samples for the pixels [x_begin, x_end): samples_per_axis^2
/// per pixel, row by row within the pixel (primary_rays' order).
void row_directions(const View& view, int y, int x_begin, int x_end, int samples_per_axis,
                    std::vector<Point>& directions);

/// The colour of a sample that hit face `hit.face` of `mesh` along the unit direction `unit`:
/// its region's colour (the patch orange, or options.colouring's), dark where the face is
/// seen from behind, Lambert-shaded by a headlight.
Rgb shade_mesh_hit(const Mesh& mesh, const embree::RayHit& hit, const Point& unit, const Point& eye,
                   const SnapshotOptions& options);

/// The background of a sample that hit nothing in row `y` of `height`: a soft vertical gradient.
Rgb background_colour(int y, int height);

/// The overlay's solids in one scene, with each triangle's colour (no scene without solids).
struct SolidScene {
  std::unique_ptr<embree::TriangleScene> scene;
  std::vector<Rgb> colour;  ///< by face of the scene
};
SolidScene solid_scene(const Overlay& overlay);

/// The colour of a sample that hit a solid.
Rgb shade_solid_hit(const SolidScene& solids, const embree::RayHit& hit, const Point& unit);

/// The overlay's lines and dots over `image` where `depth` (per pixel, the first hit's
/// distance) does not hide them, within `tolerance`.
void draw_overlay(Image& image, const View& view, const std::vector<double>& depth,
                  double tolerance, const Overlay& overlay);

}  // namespace holebench::render
