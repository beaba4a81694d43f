#include "harness/outputs/render/input_view.h"

#include "harness/outputs/render/ray_view.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace holebench::render {
namespace {

/// The pixels whose samples can see a point of some triangle: columns [x_begin, x_end) and
/// rows [y_begin, y_end), around the triangles' projected corners with a pixel to spare (a
/// triangle in front of the camera projects into the convex hull of its corners). The whole
/// picture when a corner lies behind the camera; empty when there are no triangles.
struct PixelRect {
  int x_begin = 0, x_end = 0, y_begin = 0, y_end = 0;
  bool empty() const { return x_begin >= x_end || y_begin >= y_end; }
};

class PixelRectOfPoints {
 public:
  explicit PixelRectOfPoints(const View& view) : view_(view) {}
  void add(const Point& p) {
    double x, y, depth;
    if (!view_.project(p, x, y, depth)) {
      behind_ = true;
      return;
    }
    min_x_ = std::min(min_x_, x);
    max_x_ = std::max(max_x_, x);
    min_y_ = std::min(min_y_, y);
    max_y_ = std::max(max_y_, y);
  }
  PixelRect rect() const {
    if (behind_)
      return {0, view_.width, 0, view_.height};
    if (!(min_x_ <= max_x_) || !(min_y_ <= max_y_))
      return {};
    const auto clamp = [](double v, int size) {
      return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(size)));
    };
    return {clamp(std::floor(min_x_) - 1.0, view_.width),
            clamp(std::floor(max_x_) + 2.0, view_.width),
            clamp(std::floor(min_y_) - 1.0, view_.height),
            clamp(std::floor(max_y_) + 2.0, view_.height)};
  }

 private:
  const View& view_;
  bool behind_ = false;
  double min_x_ = std::numeric_limits<double>::infinity();
  double max_x_ = -std::numeric_limits<double>::infinity();
  double min_y_ = std::numeric_limits<double>::infinity();
  double max_y_ = -std::numeric_limits<double>::infinity();
};

}  // namespace

InputView input_view(const Mesh& mesh, const embree::TriangleScene& scene, const Camera& camera,
                     const SnapshotOptions& options) {
  InputView out;
  out.camera = camera;
  out.samples_per_axis = std::max(1, options.samples_per_axis);
  const int n = out.samples_per_axis;
  const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
  const int width = options.width, height = options.height;
  const std::size_t pixels = static_cast<std::size_t>(width) * height;
  out.distance.resize(pixels * per_pixel);
  out.colour.resize(pixels * per_pixel);
  out.picture.image = Image(width, height);
  out.picture.depth.assign(pixels, std::numeric_limits<double>::infinity());
  const View view(camera, width, height);
  std::vector<Point> directions;
  std::vector<embree::RayHit> hits;
  for (int y = 0; y < height; ++y) {
    row_directions(view, y, 0, width, n, directions);
    scene.intersect_coherent(view.eye, directions, hits);
    for (int x = 0; x < width; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      Rgb sum;
      for (std::size_t k = per_pixel * x; k < per_pixel * (x + 1); ++k) {
        const std::size_t sample = pixel * per_pixel + (k - per_pixel * x);
        const embree::RayHit& hit = hits[k];
        Rgb colour;
        if (!hit.hit) {
          colour = background_colour(y, height);
          out.distance[sample] = std::numeric_limits<float>::infinity();
        } else {
          const Point unit = directions[k] / directions[k].norm();
          colour = shade_mesh_hit(mesh, hit, unit, view.eye, options);
          // Embree's distances are single precision: the float holds it exactly.
          out.distance[sample] = static_cast<float>(hit.distance);
          out.picture.depth[pixel] = std::min(out.picture.depth[pixel], hit.distance);
        }
        out.colour[sample] = colour;
        sum.r += colour.r;
        sum.g += colour.g;
        sum.b += colour.b;
      }
      const float w = 1.0f / static_cast<float>(n * n);
      out.picture.image.set(x, y, {sum.r * w, sum.g * w, sum.b * w});
    }
  }
  return out;
}

Rendering render_over_input_view(const InputView& input, const Mesh& mesh,
                                 const std::vector<int>& added,
                                 const embree::TriangleScene* added_scene,
                                 const SnapshotOptions& options, const Overlay& overlay) {
  const int width = input.picture.image.width, height = input.picture.image.height;
  if (options.width != width || options.height != height ||
      std::max(1, options.samples_per_axis) != input.samples_per_axis)
    throw std::invalid_argument(
        "render_over_input_view: the options' size or supersampling "
        "is not the input view's");
  const View view(input.camera, width, height);
  const SolidScene solids = solid_scene(overlay);
  // Only the pixels that the added faces or the overlay's solids can show in are traced.
  PixelRectOfPoints points(view);
  if (added_scene) {
    for (int f : added)
      for (auto v : mesh.fv_range(mesh.face_handle(f)))
        points.add(mesh.point(v));
  }
  for (const auto& solid : overlay.solids)
    for (const auto& p : solid.triangles.points)
      points.add(p);
  const PixelRect rect = points.rect();

  Rendering out = input.picture;
  const int n = input.samples_per_axis;
  const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
  std::vector<Point> directions;
  std::vector<embree::RayHit> hits, solid_hits;
  for (int y = rect.y_begin; !rect.empty() && y < rect.y_end; ++y) {
    row_directions(view, y, rect.x_begin, rect.x_end, n, directions);
    if (added_scene)
      added_scene->intersect_coherent(view.eye, directions, hits);
    if (solids.scene)
      solids.scene->intersect_coherent(view.eye, directions, solid_hits);
    for (int x = rect.x_begin; x < rect.x_end; ++x) {
      const std::size_t pixel = static_cast<std::size_t>(y) * width + x;
      double& d = out.depth[pixel];
      d = std::numeric_limits<double>::infinity();
      Rgb sum;
      for (std::size_t s = 0; s < per_pixel; ++s) {
        const std::size_t k = per_pixel * (x - rect.x_begin) + s;
        const std::size_t sample = pixel * per_pixel + s;
        const double input_distance = input.distance[sample];
        const bool input_hit = std::isfinite(input_distance);
        const embree::RayHit added_hit = added_scene ? hits[k] : embree::RayHit{};
        const bool added_wins =
            added_hit.hit && (!input_hit || added_hit.distance < input_distance);
        const bool mesh_hit = added_wins || input_hit;
        const double mesh_distance = added_wins ? added_hit.distance : input_distance;
        const embree::RayHit solid_hit = solids.scene ? solid_hits[k] : embree::RayHit{};
        const Point unit = directions[k] / directions[k].norm();
        Rgb colour;
        if (solid_hit.hit && (!mesh_hit || solid_hit.distance < mesh_distance)) {
          d = std::min(d, solid_hit.distance);
          colour = shade_solid_hit(solids, solid_hit, unit);
        } else if (added_wins) {
          d = std::min(d, mesh_distance);
          colour = shade_mesh_hit(mesh, added_hit, unit, view.eye, options);
        } else {
          if (input_hit)
            d = std::min(d, mesh_distance);
          colour = input.colour[sample];  // the input's face, or the background
        }
        sum.r += colour.r;
        sum.g += colour.g;
        sum.b += colour.b;
      }
      const float w = 1.0f / static_cast<float>(n * n);
      out.image.set(x, y, {sum.r * w, sum.g * w, sum.b * w});
    }
  }
  draw_overlay(out.image, view, out.depth, 0.01 * input.camera.distance, overlay);
  return out;
}

}  // namespace holebench::render
