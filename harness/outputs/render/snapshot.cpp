#include "harness/outputs/render/snapshot.h"

#include "core/geometry.h"
#include "metrics/embree/triangle_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace holebench::render {

Rgb region_colour(int id) {
  if (id < 0)
    return {0.6f, 0.6f, 0.6f};
  // Golden-angle hues: neighbouring ids get clearly different colours.
  const float hue = std::fmod(0.12f + 0.618034f * static_cast<float>(id), 1.0f) * 6.0f;
  const float x = 1.0f - std::abs(std::fmod(hue, 2.0f) - 1.0f);
  Rgb c;
  switch (static_cast<int>(hue)) {
    case 0:
      c = {1, x, 0};
      break;
    case 1:
      c = {x, 1, 0};
      break;
    case 2:
      c = {0, 1, x};
      break;
    case 3:
      c = {0, x, 1};
      break;
    case 4:
      c = {x, 0, 1};
      break;
    default:
      c = {1, 0, x};
      break;
  }
  // Pastel: mix with white so that shading stays readable.
  return {0.35f + 0.55f * c.r, 0.35f + 0.55f * c.g, 0.35f + 0.55f * c.b};
}

Rgb patch_colour() {
  return {1.0f, 0.42f, 0.05f};
}

Camera frame_sphere(const Point& target, double radius, const Point& direction,
                    double field_of_view_degrees) {
  Camera camera;
  camera.target = target;
  camera.direction = direction / direction.norm();
  camera.field_of_view_degrees = field_of_view_degrees;
  camera.distance = 1.05 * radius / std::sin(0.5 * field_of_view_degrees * M_PI / 180.0);
  return camera;
}

namespace {

// The camera's frame and projection.
struct View {
  Point eye, forward, right, up;
  double half_width, half_height;
  int width, height;

  View(const Camera& camera, int w, int h) : width(w), height(h) {
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

  Point ray(double x, double y) const {
    const double u = (x / width * 2.0 - 1.0) * half_width;
    const double v = (1.0 - y / height * 2.0) * half_height;
    return forward + right * u + up * v;
  }

  // Pixel coordinates and distance from the eye; false behind the camera.
  bool project(const Point& p, double& x, double& y, double& depth) const {
    const Point d = p - eye;
    const double z = OpenMesh::dot(d, forward);
    if (z <= 1e-12)
      return false;
    x = (OpenMesh::dot(d, right) / z / half_width + 1.0) * 0.5 * width;
    y = (1.0 - OpenMesh::dot(d, up) / z / half_height) * 0.5 * height;
    depth = d.norm();
    return true;
  }
};

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

}  // namespace

TriangleSoup arrow_solid(const Point& from, const Point& to, double radius, int segments) {
  const Point axis = to - from;
  const double length = axis.norm();
  const Point r = axis / length;
  // Two unit vectors across the axis.
  Point u = OpenMesh::cross(r, std::abs(r[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0));
  u /= u.norm();
  const Point v = OpenMesh::cross(r, u);
  // The profile (position along the axis, radius) from the tail's pole to the tip's.
  const double head = 0.25 * length;
  const std::vector<std::pair<double, double>> profile = {
      {0.0, radius}, {length - head, radius}, {length - head, 2.5 * radius}};
  TriangleSoup soup;
  soup.points.push_back(from);  // 0: the tail's pole
  for (const auto& [along, width] : profile) {
    for (int j = 0; j < segments; ++j) {
      const double angle = 2.0 * M_PI * j / segments;
      soup.points.push_back(from + r * along + (u * std::cos(angle) + v * std::sin(angle)) * width);
    }
  }
  const int tip = static_cast<int>(soup.points.size());
  soup.points.push_back(to);
  const auto ring = [segments](int k, int j) { return 1 + k * segments + (j % segments); };
  const int rings = static_cast<int>(profile.size());
  for (int j = 0; j < segments; ++j) {
    soup.triangles.push_back({0, ring(0, j + 1), ring(0, j)});  // the tail's cap
    for (int k = 0; k + 1 < rings; ++k) {
      soup.triangles.push_back({ring(k, j), ring(k, j + 1), ring(k + 1, j + 1)});
      soup.triangles.push_back({ring(k, j), ring(k + 1, j + 1), ring(k + 1, j)});
    }
    soup.triangles.push_back({ring(rings - 1, j), ring(rings - 1, j + 1), tip});  // the cone
  }
  return soup;
}

std::optional<Projection> project(const Camera& camera, int width, int height, const Point& p) {
  const View view(camera, width, height);
  Projection out;
  if (!view.project(p, out.x, out.y, out.depth))
    return std::nullopt;
  return out;
}

Point eye_of(const Camera& camera) {
  return camera.target - camera.direction / camera.direction.norm() * camera.distance;
}

PrimaryRays primary_rays(const Camera& camera, const SnapshotOptions& options) {
  const View view(camera, options.width, options.height);
  const int n = std::max(1, options.samples_per_axis);
  PrimaryRays rays{view.eye, {}};
  rays.directions.reserve(static_cast<std::size_t>(options.width) * options.height * n * n);
  for (int y = 0; y < options.height; ++y)
    for (int x = 0; x < options.width; ++x)
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx)
          rays.directions.push_back(view.ray(x + (sx + 0.5) / n, y + (sy + 0.5) / n));
  return rays;
}

Image render_snapshot(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options,
                      const Overlay& overlay) {
  return render_with_depth(mesh, camera, options, overlay).image;
}

Rendering render_with_depth(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options,
                            const Overlay& overlay) {
  const embree::TriangleScene scene(mesh);
  return render_with_depth(mesh, scene, camera, options, overlay);
}

Rendering render_with_depth(const Mesh& mesh, const embree::TriangleScene& scene,
                            const Camera& camera, const SnapshotOptions& options,
                            const Overlay& overlay) {
  // The overlay's solids in one scene of their own, with each triangle's colour.
  TriangleSoup solids;
  std::vector<Rgb> solid_colour;
  for (const auto& solid : overlay.solids) {
    const int offset = static_cast<int>(solids.points.size());
    solids.points.insert(solids.points.end(), solid.triangles.points.begin(),
                         solid.triangles.points.end());
    for (const auto& t : solid.triangles.triangles) {
      solids.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
      solid_colour.push_back(solid.colour);
    }
  }
  std::optional<embree::TriangleScene> solid_scene;
  if (!solids.triangles.empty())
    solid_scene.emplace(build_mesh(solids, {"the overlay's solids", false}));
  Image image(options.width, options.height);
  const View view(camera, options.width, options.height);
  const int n = std::max(1, options.samples_per_axis);
  std::vector<double> depth(static_cast<std::size_t>(options.width) * options.height,
                            std::numeric_limits<double>::infinity());

  // One row at a time: its rays (n x n per pixel) traced as one coherent stream.
  const std::size_t per_pixel = static_cast<std::size_t>(n) * n;
  std::vector<Point> directions(per_pixel * options.width);
  std::vector<embree::RayHit> hits, solid_hits;
  for (int y = 0; y < options.height; ++y) {
    for (int x = 0; x < options.width; ++x)
      for (int sy = 0; sy < n; ++sy)
        for (int sx = 0; sx < n; ++sx)
          directions[per_pixel * x + sy * n + sx] =
              view.ray(x + (sx + 0.5) / n, y + (sy + 0.5) / n);
    scene.intersect_coherent(view.eye, directions, hits);
    if (solid_scene)
      solid_scene->intersect_coherent(view.eye, directions, solid_hits);
    for (int x = 0; x < options.width; ++x) {
      Rgb sum;
      for (std::size_t k = per_pixel * x; k < per_pixel * (x + 1); ++k) {
        const Point unit = directions[k] / directions[k].norm();
        const embree::RayHit& hit = hits[k];
        const embree::RayHit solid_hit = solid_scene ? solid_hits[k] : embree::RayHit{};
        Rgb colour;
        if (solid_hit.hit && (!hit.hit || solid_hit.distance < hit.distance)) {
          auto& d = depth[static_cast<std::size_t>(y) * options.width + x];
          d = std::min(d, solid_hit.distance);
          const double facing = std::abs(OpenMesh::dot(solid_hit.normal, unit));
          const float light = static_cast<float>(0.3 + 0.7 * facing);
          const Rgb& base = solid_colour[solid_hit.face];
          colour = {base.r * light, base.g * light, base.b * light};
        } else if (!hit.hit) {
          // A soft vertical gradient as background.
          const float t = static_cast<float>(1.0 - static_cast<double>(y) / options.height);
          colour = {0.93f - 0.12f * t, 0.94f - 0.10f * t, 0.96f - 0.05f * t};
        } else {
          auto& d = depth[static_cast<std::size_t>(y) * options.width + x];
          d = std::min(d, hit.distance);  // t along the unit ray: the distance
          const FaceHandle f = mesh.face_handle(hit.face);
          const double facing = -OpenMesh::dot(hit.normal, unit);
          const float light = static_cast<float>(0.25 + 0.75 * std::abs(facing));
          Rgb base = is_new(mesh, f) ? patch_colour() : region_colour(region(mesh, f));
          if (options.colouring) {
            if (const auto own = options.colouring(f, view.eye + unit * hit.distance))
              base = *own;
          }
          if (facing < 0.0)
            base = {0.35f, 0.08f, 0.12f};  // the inside, seen through a hole
          colour = {base.r * light, base.g * light, base.b * light};
        }
        sum.r += colour.r;
        sum.g += colour.g;
        sum.b += colour.b;
      }
      const float w = 1.0f / static_cast<float>(n * n);
      image.set(x, y, {sum.r * w, sum.g * w, sum.b * w});
    }
  }
  draw_overlay(image, view, depth, 0.01 * camera.distance, overlay);
  return {std::move(image), std::move(depth)};
}

}  // namespace holebench::render
