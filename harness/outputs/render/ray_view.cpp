#include "harness/outputs/render/ray_view.h"

#include "core/mesh_builder.h"

#include <algorithm>
#include <cmath>

namespace holebench::render {

View::View(const Camera& camera, int w, int h) : width(w), height(h) {
  forward = camera.direction / camera.direction.norm();
  // "up" is +z unless the camera looks along z.
  const Point up_hint = std::abs(forward[2]) < 0.95 ? Point(0, 0, 1) : Point(0, 1, 0);
  right = OpenMesh::cross(forward, up_hint);
  right /= right.norm();
  up = OpenMesh::cross(right, forward);
  eye = camera.target - forward * camera.distance;
  half_height = std::tan(0.5 * camera.field_of_view_degrees * M_PI / 180.0);
  half_width = half_height * w / h;
}

Point View::ray(double x, double y) const {
  const double u = (x / width * 2.0 - 1.0) * half_width;
  const double v = (1.0 - y / height * 2.0) * half_height;
  return forward + right * u + up * v;
}

bool View::project(const Point& p, double& x, double& y, double& depth) const {
  const Point d = p - eye;
  const double z = OpenMesh::dot(d, forward);
  if (z <= 1e-12)
    return false;
  x = (OpenMesh::dot(d, right) / z / half_width + 1.0) * 0.5 * width;
  y = (1.0 - OpenMesh::dot(d, up) / z / half_height) * 0.5 * height;
  depth = d.norm();
  return true;
}

void row_directions(const View& view, int y, int x_begin, int x_end, int samples_per_axis,
                    std::vector<Point>& directions) {
  const int n = samples_per_axis;
  const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
  directions.resize(per_pixel * static_cast<std::size_t>(std::max(0, x_end - x_begin)));
  for (int x = x_begin; x < x_end; ++x)
    for (int sy = 0; sy < n; ++sy)
      for (int sx = 0; sx < n; ++sx)
        directions[per_pixel * (x - x_begin) + sy * n + sx] =
            view.ray(x + (sx + 0.5) / n, y + (sy + 0.5) / n);
}

Rgb shade_mesh_hit(const Mesh& mesh, const embree::RayHit& hit, const Point& unit, const Point& eye,
                   const SnapshotOptions& options) {
  const FaceHandle f = mesh.face_handle(hit.face);
  const double facing = -OpenMesh::dot(hit.normal, unit);
  const float light = static_cast<float>(0.25 + 0.75 * std::abs(facing));
  Rgb base = is_new(mesh, f) ? patch_colour() : region_colour(region(mesh, f));
  if (options.colouring) {
    if (const auto own = options.colouring(f, eye + unit * hit.distance))
      base = *own;
  }
  if (facing < 0.0)
    base = {0.35f, 0.08f, 0.12f};  // the inside, seen through a hole
  return {base.r * light, base.g * light, base.b * light};
}

Rgb background_colour(int y, int height) {
  const float t = static_cast<float>(1.0 - static_cast<double>(y) / height);
  return {0.93f - 0.12f * t, 0.94f - 0.10f * t, 0.96f - 0.05f * t};
}

SolidScene solid_scene(const Overlay& overlay) {
  TriangleSoup solids;
  SolidScene out;
  for (const auto& solid : overlay.solids) {
    const int offset = static_cast<int>(solids.points.size());
    solids.points.insert(solids.points.end(), solid.triangles.points.begin(),
                         solid.triangles.points.end());
    for (const auto& t : solid.triangles.triangles) {
      solids.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
      out.colour.push_back(solid.colour);
    }
  }
  if (!solids.triangles.empty())
    out.scene = std::make_unique<embree::TriangleScene>(
        build_mesh(solids, {"the overlay's solids", false}));
  return out;
}

Rgb shade_solid_hit(const SolidScene& solids, const embree::RayHit& hit, const Point& unit) {
  const double facing = std::abs(OpenMesh::dot(hit.normal, unit));
  const float light = static_cast<float>(0.3 + 0.7 * facing);
  const Rgb& base = solids.colour[hit.face];
  return {base.r * light, base.g * light, base.b * light};
}

namespace {

void paint_disc(Image& image, const std::vector<double>& depth, double tolerance, double x,
                double y, double point_depth, float radius, const Rgb& colour) {
  const int r = static_cast<int>(std::ceil(radius));
  for (int dy = -r; dy <= r; ++dy) {
    for (int dx = -r; dx <= r; ++dx) {
      const int px = static_cast<int>(std::floor(x)) + dx;
      const int py = static_cast<int>(std::floor(y)) + dy;
      if (px < 0 || py < 0 || px >= image.width || py >= image.height)
        continue;
      if (dx * dx + dy * dy > radius * radius)
        continue;
      if (point_depth > depth[static_cast<std::size_t>(py) * image.width + px] + tolerance)
        continue;
      image.set(px, py, colour);
    }
  }
}

}  // namespace

void draw_overlay(Image& image, const View& view, const std::vector<double>& depth,
                  double tolerance, const Overlay& overlay) {
  for (const auto& line : overlay.lines) {
    double xa, ya, da, xb, yb, db;
    if (!view.project(line.a, xa, ya, da) || !view.project(line.b, xb, yb, db))
      continue;
    const int steps = std::max(1, static_cast<int>(std::ceil(std::hypot(xb - xa, yb - ya))));
    for (int i = 0; i <= steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      double x, y, d;
      if (!view.project(line.a + (line.b - line.a) * t, x, y, d))
        continue;
      paint_disc(image, depth, tolerance, x, y, d, 0.5f * line.width_px, line.colour);
    }
  }
  for (const auto& dot : overlay.dots) {
    double x, y, d;
    if (view.project(dot.p, x, y, d))
      paint_disc(image, depth, tolerance, x, y, d, dot.radius_px, dot.colour);
  }
}

}  // namespace holebench::render
