#include "methods/slice_loft/holes_and_islands.h"

#include "core/polygon_2d.h"

#include <cmath>
#include <limits>

namespace holebench::slice_loft {
namespace {

using Vec2 = Point2d;
Vec2 operator-(Vec2 a, Vec2 b) {
  return {a.x - b.x, a.y - b.y};
}
double cross(Vec2 a, Vec2 b) {
  return a.x * b.y - a.y * b.x;
}

// An orthonormal frame (u, v) of a plane with u x v = n.
struct PlaneFrame {
  Point origin, u, v, n;
  explicit PlaneFrame(const Plane& plane) : origin(plane.point), n(plane.normal) {
    const Point helper = std::abs(n[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
    u = OpenMesh::cross(n, helper).normalized();
    v = OpenMesh::cross(n, u);
  }
  Vec2 project(const Point& p) const {
    const Point d = p - origin;
    return {OpenMesh::dot(d, u), OpenMesh::dot(d, v)};
  }
};

Plane plane_of_maximum_span(const Mesh& mesh, const std::vector<VertexHandle>& vertices) {
  std::vector<Point> points;
  for (auto v : vertices)
    points.push_back(mesh.point(v));
  const PlaneFit fit = fit_plane(points);
  if (fit.valid)
    return fit.plane;
  // Collinear or too few points: Newell's normal, or any.
  Plane plane;
  Point centroid(0, 0, 0), normal(0, 0, 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    centroid += points[i];
    normal += OpenMesh::cross(points[i], points[(i + 1) % points.size()]);
  }
  plane.point = centroid / static_cast<double>(std::max<std::size_t>(1, points.size()));
  plane.normal = normal.norm() > 0.0 ? normal.normalized() : Point(0, 0, 1);
  return plane;
}

// The D-contour of 4.1.1: each edge a chord of the reference circle (perimeter equal to the
// contour's), in the projection's sense of rotation.
std::vector<Vec2> develop_contour(const Mesh& mesh, const Contour& contour,
                                  const PlaneFrame& frame) {
  const auto& vs = contour.vertices;
  std::vector<Vec2> projected;
  double perimeter = 0.0;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    projected.push_back(frame.project(mesh.point(vs[i])));
    perimeter += (mesh.point(vs[(i + 1) % vs.size()]) - mesh.point(vs[i])).norm();
  }
  const double sense = signed_area_2d(projected) >= 0.0 ? 1.0 : -1.0;
  const double radius = perimeter / (2.0 * M_PI);
  std::vector<Vec2> developed;
  double angle = 0.0;
  for (std::size_t i = 0; i < vs.size(); ++i) {
    developed.push_back({radius * std::cos(sense * angle), radius * std::sin(sense * angle)});
    angle += (mesh.point(vs[(i + 1) % vs.size()]) - mesh.point(vs[i])).norm() / radius;
  }
  return developed;
}

}  // namespace

bool is_island(const Mesh& mesh, const Contour& contour) {
  const auto& vs = contour.vertices;
  const std::size_t n = vs.size();
  const PlaneFrame frame(contour.span_plane);
  const std::vector<Vec2> developed = develop_contour(mesh, contour, frame);

  // Reference edge: the edge closest to orthogonal to the plane's normal.
  std::size_t reference = 0;
  double best = std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < n; ++i) {
    const Point d = mesh.point(vs[(i + 1) % n]) - mesh.point(vs[i]);
    const double c = std::abs(OpenMesh::dot(d, frame.n)) / std::max(d.norm(), 1e-300);
    if (c < best) {
      best = c;
      reference = i;
    }
  }
  const HalfedgeHandle h = contour.loop.halfedges[reference];
  const FaceHandle f = mesh.face_handle(mesh.opposite_halfedge_handle(h));
  const VertexHandle a = mesh.from_vertex_handle(h), b = mesh.to_vertex_handle(h);
  VertexHandle x;
  for (auto fv : mesh.fv_range(f)) {
    if (fv != a && fv != b)
      x = fv;
  }
  // 4.1.2: the third vertex on the side of the developed edge the triangle is on.
  const Vec2 pa = frame.project(mesh.point(a)), pb = frame.project(mesh.point(b)),
             px = frame.project(mesh.point(x));
  const double side = cross(pb - pa, px - pa) >= 0.0 ? 1.0 : -1.0;
  const Vec2 da = developed[reference], db = developed[(reference + 1) % n];
  const double c = std::hypot(db.x - da.x, db.y - da.y);
  const double la = (mesh.point(x) - mesh.point(a)).norm();
  const double lb = (mesh.point(x) - mesh.point(b)).norm();
  const double t = (la * la - lb * lb + c * c) / (2.0 * c);
  const double height = std::sqrt(std::max(0.0, la * la - t * t));
  const Vec2 dir{(db.x - da.x) / c, (db.y - da.y) / c};
  const Vec2 dx{da.x + t * dir.x - side * height * dir.y, da.y + t * dir.y + side * height * dir.x};
  const Vec2 centroid{(da.x + db.x + dx.x) / 3.0, (da.y + db.y + dx.y) / 3.0};
  return inside_polygon_2d(developed, centroid);
}

HolesAndIslands identify_holes_and_islands(const Mesh& mesh,
                                           const HoleIdentificationOptions& options) {
  HolesAndIslands result;
  for (auto& loop : find_boundary_loops(mesh)) {
    Contour contour;
    contour.vertices = loop_vertices(mesh, loop);
    contour.loop = std::move(loop);
    contour.span_plane = plane_of_maximum_span(mesh, contour.vertices);
    contour.island = contour.vertices.size() >= 3 && is_island(mesh, contour);
    result.contours.push_back(std::move(contour));
  }

  auto make_hole = [&](int index, bool orphan) {
    const Contour& contour = result.contours[index];
    Hole hole;
    hole.contour = index;
    hole.boundary = contour.loop.halfedges;
    hole.orphan_island = orphan;
    hole.box.min = hole.box.max = mesh.point(contour.vertices.front());
    for (auto v : contour.vertices) {
      hole.box.min.minimize(mesh.point(v));
      hole.box.max.maximize(mesh.point(v));
    }
    hole.mean_edge_length = loop_length(mesh, contour.loop) / contour.loop.size();
    return hole;
  };
  for (std::size_t i = 0; i < result.contours.size(); ++i) {
    if (!result.contours[i].island)
      result.holes.push_back(make_hole(static_cast<int>(i), false));
  }

  // Clustering: an island belongs to the smallest hole whose projection on its plane of
  // maximum span contains the island's and that is nearer than the hole's size.
  for (std::size_t i = 0; i < result.contours.size(); ++i) {
    const Contour& island = result.contours[i];
    if (!island.island)
      continue;
    Point centroid(0, 0, 0);
    for (auto v : island.vertices)
      centroid += mesh.point(v);
    centroid /= static_cast<double>(island.vertices.size());
    Hole* owner = nullptr;
    for (auto& hole : result.holes) {
      const Contour& outer = result.contours[hole.contour];
      const PlaneFrame frame(outer.span_plane);
      std::vector<Vec2> polygon;
      for (auto v : outer.vertices)
        polygon.push_back(frame.project(mesh.point(v)));
      const double size = hole.box.diagonal();
      if (!inside_polygon_2d(polygon, frame.project(centroid)) ||
          std::abs(outer.span_plane.signed_distance(centroid)) > size)
        continue;
      if (!owner || size < owner->box.diagonal())
        owner = &hole;
    }
    if (owner)
      owner->islands.push_back(static_cast<int>(i));
    else
      result.holes.push_back(make_hole(static_cast<int>(i), true));
  }

  // Influencing area: triangles inside the enlarged hole-enclosing box.
  for (auto& hole : result.holes) {
    const double margin = std::max(options.influence_margin_rel_box * hole.box.diagonal(),
                                   options.min_influence_margin_edges * hole.mean_edge_length);
    const Point lo = hole.box.min - Point(margin, margin, margin);
    const Point hi = hole.box.max + Point(margin, margin, margin);
    for (auto f : mesh.faces()) {
      bool inside = true;
      for (auto v : f.vertices()) {
        const Point& p = mesh.point(v);
        for (int k = 0; k < 3 && inside; ++k)
          inside = p[k] >= lo[k] && p[k] <= hi[k];
      }
      if (inside)
        hole.influencing.push_back(f);
    }
  }
  return result;
}

}  // namespace holebench::slice_loft
