#include "harness/outputs/render/case_view.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace holebench::render {

Camera hole_camera(const Case& c) {
  Point normal(0, 0, 0);
  Point centroid(0, 0, 0);
  double area = 0.0;
  for (const auto& hole : c.holes) {
    for (int index : hole.removed_faces) {
      const FaceHandle f = c.complete.face_handle(index);
      const double a = face_area(c.complete, f);
      normal += face_normal(c.complete, f) * a;
      centroid += face_centroid(c.complete, f) * a;
      area += a;
    }
  }
  if (area == 0.0 || normal.norm() == 0.0) {
    normal = Point(1, 1, 1);
    centroid = bounding_box(c.complete).center();
  } else {
    centroid /= area;
  }
  normal /= normal.norm();
  // Enough context around the hole to read it, never more than the whole model.
  double extent = 0.0;
  for (const auto& hole : c.holes) {
    for (int index : hole.removed_faces) {
      extent = std::max(
          extent, (face_centroid(c.complete, c.complete.face_handle(index)) - centroid).norm());
    }
  }
  const BoundingBox box = bounding_box(c.complete);
  const double radius = std::min(0.55 * box.diagonal() + (box.center() - centroid).norm(),
                                 std::max(3.0 * extent, 0.3 * box.diagonal()));
  const Point tilt = Point(0.35, -0.45, 0.3);
  const Point direction = -(normal + tilt * 0.6);
  return frame_sphere(centroid, radius, direction);
}

Overlay hole_overlay(const Mesh& holed, double normal_length) {
  Overlay overlay;
  const Rgb red{0.85f, 0.05f, 0.05f};
  const Rgb dark{0.25f, 0.0f, 0.0f};
  const Rgb black{0.02f, 0.02f, 0.02f};
  std::map<int, std::pair<Point, double>> near_hole;  // region -> (sum of centroids, count)
  for (const auto& loop : find_boundary_loops(holed)) {
    int previous = kNoRegion;
    for (std::size_t i = 0; i <= loop.size(); ++i) {
      const auto h = loop.halfedges[i % loop.size()];
      const auto face = holed.opposite_face_handle(h);
      const int id = region(holed, face);
      if (i < loop.size()) {
        overlay.lines.push_back({holed.point(holed.from_vertex_handle(h)),
                                 holed.point(holed.to_vertex_handle(h)), red, 3.0f});
        auto& entry = near_hole.try_emplace(id, Point(0, 0, 0), 0.0).first->second;
        entry.first += face_centroid(holed, face);
        entry.second += 1.0;
      }
      if (i > 0 && id != previous && id != kNoRegion && previous != kNoRegion) {
        overlay.dots.push_back({holed.point(holed.from_vertex_handle(h)), dark, 5.0f});
      }
      previous = id;
    }
  }
  // One normal per region next to a hole, at the mean of its faces along the hole.
  // Point() leaves its coordinates uninitialised (OpenMesh): each sum starts at zero.
  std::map<int, Point> normal_sum;
  for (auto f : holed.faces()) {
    normal_sum.try_emplace(region(holed, f), 0.0, 0.0, 0.0).first->second +=
        face_normal(holed, f) * face_area(holed, f);
  }
  for (const auto& [id, entry] : near_hole) {
    const auto sum = normal_sum.find(id);
    if (id == kNoRegion || sum == normal_sum.end() || sum->second.norm() == 0.0)
      continue;
    const Point base = entry.first / entry.second;
    const Point n = sum->second / sum->second.norm();
    overlay.lines.push_back({base, base + n * normal_length, black, 2.0f});
  }
  return overlay;
}

void add_guidance_arrows(Overlay& overlay, const Case& c, const MethodResult& result) {
  const double diagonal = bounding_box(c.complete).diagonal();
  for (const auto& hole : result.holes) {
    if (!hole.arrow)
      continue;
    const double length =
        std::max(0.05 * diagonal, 0.8 * (hole.centroid - hole.arrow->position).norm());
    add_arrow(overlay, *hole.arrow, length);
  }
}

void add_arrow(Overlay& overlay, const GuidanceArrow& arrow, double length) {
  const Rgb blue{0.05f, 0.15f, 0.75f};
  const Point r = arrow.direction / arrow.direction.norm();
  // A shaded 3D arrow from P along r (it hides and is hidden by the model), with P marked.
  overlay.solids.push_back(
      {arrow_solid(arrow.position, arrow.position + r * length, 0.035 * length), blue});
  overlay.dots.push_back({arrow.position, blue, 4.0f});
}

Image job_snapshot(const Case& c, const MethodResult& result, const SnapshotOptions& options) {
  Camera camera = hole_camera(c);
  // Widen the view where an arrow starts outside it.
  const double half_angle = 0.5 * camera.field_of_view_degrees * M_PI / 180.0;
  double radius = camera.distance * std::sin(half_angle) / 1.05;
  for (const auto& hole : result.holes) {
    if (hole.arrow)
      radius = std::max(radius, 1.1 * (hole.arrow->position - camera.target).norm());
  }
  camera.distance = 1.05 * radius / std::sin(half_angle);
  Overlay overlay;
  add_guidance_arrows(overlay, c, result);
  return render_snapshot(result.repaired, camera, options, overlay);
}

}  // namespace holebench::render
