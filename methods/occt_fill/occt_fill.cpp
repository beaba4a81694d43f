#include "methods/occt_fill/occt_fill.h"

#include "core/boundary_loops.h"
#include "core/plane_fit.h"
#include "core/polygon.h"
#include "core/polygon_2d.h"
#include "core/stopwatch.h"
#include "methods/common/planar_polygon_triangulation.h"

#include <GeomPlate_BuildPlateSurface.hxx>
#include <GeomPlate_PointConstraint.hxx>
#include <GeomPlate_Surface.hxx>
#include <Geom_Plane.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <Standard_Failure.hxx>
#include <gp_Ax3.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>

namespace holebench {
namespace {

using Point2 = std::array<double, 2>;

/// One boundary loop with what the filling needs of it.
struct HoleLoop {
  std::vector<VertexHandle> vertices;
  std::vector<Point> points;
  double length = 0.0;
  Point newell{0.0, 0.0, 0.0};
  Point centroid{0.0, 0.0, 0.0};
  double diameter = 0.0;
};

/// A hole: its loop and the island loops inside it.
struct HoleGroup {
  std::size_t outer = 0;
  std::vector<std::size_t> islands;
};

/// The plate's frame: the hole's least-squares plane, whose coordinates are the plate's
/// parameters (P(u, v) = origin + u x + v y).
struct PlateFrame {
  gp_Ax3 axes;
  Point origin, x, y, normal;
  Point2 uv(const Point& p) const {
    const Point d = p - origin;
    return {OpenMesh::dot(d, x), OpenMesh::dot(d, y)};
  }
};

HoleLoop make_hole_loop(const Mesh& mesh, const BoundaryLoop& loop) {
  HoleLoop hole;
  hole.vertices = loop_vertices(mesh, loop);
  hole.points = loop_points(mesh, loop);
  hole.length = loop_length(mesh, loop);
  hole.newell = newell_normal(hole.points);
  hole.centroid = loop_centroid(mesh, loop);
  for (const Point& a : hole.points) {
    for (const Point& b : hole.points)
      hole.diameter = std::max(hole.diameter, (a - b).norm());
  }
  return hole;
}

/// `island` is an island of `hole`: it runs the other way round (the surface lies inside
/// it), and seen along the hole's normal all its points lie inside the hole's loop, within
/// the hole's diameter of its plane.
bool is_island_of(const HoleLoop& island, const HoleLoop& hole) {
  if (hole.newell.norm() == 0.0 || OpenMesh::dot(island.newell, hole.newell) >= 0.0)
    return false;
  const Point normal = hole.newell.normalized();
  const Point& origin = hole.points.front();
  for (const Point& p : island.points) {
    if (std::abs(OpenMesh::dot(p - origin, normal)) > hole.diameter ||
        !inside_projected_polygon(hole.points, normal, p))
      return false;
  }
  return true;
}

/// Each loop is a hole, or (options.attach_islands) an island of the smallest hole that
/// contains it.
std::vector<HoleGroup> group_islands(const std::vector<HoleLoop>& loops, bool attach_islands) {
  std::vector<int> owner(loops.size(), -1);
  if (attach_islands) {
    for (std::size_t i = 0; i < loops.size(); ++i) {
      for (std::size_t j = 0; j < loops.size(); ++j) {
        if (i == j || !is_island_of(loops[i], loops[j]))
          continue;
        if (owner[i] < 0 || loops[j].length < loops[static_cast<std::size_t>(owner[i])].length)
          owner[i] = static_cast<int>(j);
      }
    }
  }
  std::vector<HoleGroup> groups;
  std::vector<int> group_of(loops.size(), -1);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (owner[i] >= 0 && owner[static_cast<std::size_t>(owner[i])] < 0)
      continue;  // an island (of a loop that is itself a hole)
    group_of[i] = static_cast<int>(groups.size());
    groups.push_back({i, {}});
  }
  for (std::size_t i = 0; i < loops.size(); ++i) {
    if (group_of[i] < 0)
      groups[static_cast<std::size_t>(group_of[static_cast<std::size_t>(owner[i])])]
          .islands.push_back(i);
  }
  return groups;
}

/// The area-weighted normal of the input faces around `v` (zero where it has none).
Point surface_normal(const Mesh& mesh, VertexHandle v) {
  Point sum(0.0, 0.0, 0.0);
  for (auto f : mesh.vf_range(v)) {
    auto fv = mesh.cfv_begin(f);
    const Point a = mesh.point(*fv), b = mesh.point(*++fv), c = mesh.point(*++fv);
    sum += OpenMesh::cross(b - a, c - a);
  }
  return sum.norm() > 0.0 ? sum.normalized() : sum;
}

/// The surface's normal at boundary vertex `v`, unbiased by the missing side: the faces
/// around a boundary vertex lie on one side of it, so their mean normal tilts away from the
/// hole on a curved surface. Fitted instead as the gradient at `v` of a quadric height field
/// z = d x + e y + a x^2 + b xy + c y^2 over the tangent plane of the mean normal, through
/// the vertices of the faces within two rings whose normals lie within `max_angle` of it
/// (so a sharp edge bounds the fit). Falls back to the mean normal with fewer than eight
/// such vertices or a singular fit.
Point fitted_normal(const Mesh& mesh, VertexHandle v, double max_angle) {
  const Point mean = surface_normal(mesh, v);
  if (mean.norm() == 0.0)
    return mean;
  Point ex = OpenMesh::cross(mean, std::abs(mean[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0));
  ex.normalize();
  const Point ey = OpenMesh::cross(mean, ex);
  const double min_cos = std::cos(max_angle);
  std::set<int> ring{v.idx()}, faces_seen, points;
  for (int depth = 0; depth < 2; ++depth) {
    std::set<int> next = ring;
    for (int r : ring) {
      for (auto f : mesh.vf_range(mesh.vertex_handle(static_cast<unsigned>(r)))) {
        if (!faces_seen.insert(f.idx()).second)
          continue;
        auto fv = mesh.cfv_begin(f);
        const Point a = mesh.point(*fv), b = mesh.point(*++fv), c = mesh.point(*++fv);
        const Point n = OpenMesh::cross(b - a, c - a);
        if (n.norm() == 0.0 || OpenMesh::dot(n.normalized(), mean) < min_cos)
          continue;
        for (auto u : mesh.fv_range(f)) {
          next.insert(u.idx());
          points.insert(u.idx());
        }
      }
    }
    ring = next;
  }
  points.erase(v.idx());
  if (points.size() < 8)
    return mean;
  // Normal equations of the least-squares fit, 5 unknowns (d, e, a, b, c).
  double m[5][6] = {};
  const Point origin = mesh.point(v);
  for (int i : points) {
    const Point q = mesh.point(mesh.vertex_handle(static_cast<unsigned>(i))) - origin;
    const double x = OpenMesh::dot(q, ex), y = OpenMesh::dot(q, ey), z = OpenMesh::dot(q, mean);
    const double row[5] = {x, y, x * x, x * y, y * y};
    for (int r = 0; r < 5; ++r) {
      for (int c = 0; c < 5; ++c)
        m[r][c] += row[r] * row[c];
      m[r][5] += row[r] * z;
    }
  }
  for (int col = 0; col < 5; ++col) {
    int pivot = col;
    for (int r = col + 1; r < 5; ++r) {
      if (std::abs(m[r][col]) > std::abs(m[pivot][col]))
        pivot = r;
    }
    if (std::abs(m[pivot][col]) < 1e-300)
      return mean;
    std::swap(m[col], m[pivot]);
    for (int r = 0; r < 5; ++r) {
      if (r == col)
        continue;
      const double factor = m[r][col] / m[col][col];
      for (int c = col; c < 6; ++c)
        m[r][c] -= factor * m[col][c];
    }
  }
  const double d = m[0][5] / m[0][0], e = m[1][5] / m[1][1];
  Point normal = mean - ex * d - ey * e;
  return std::isfinite(normal.norm()) && normal.norm() > 0.0 ? normal.normalized() : mean;
}

gp_Pnt to_gp(const Point& p) {
  return gp_Pnt(p[0], p[1], p[2]);
}

/// Every `loop`'s vertices, at most `budget` of them evenly spread, as point constraints:
/// G1 (the tangent plane of the surrounding surface) where the vertex has a normal and
/// tangents are on, G0 otherwise.
std::size_t add_constraints(const Mesh& mesh, const HoleLoop& loop, int budget, double tolerance,
                            const OcctFillOptions& options, GeomPlate_BuildPlateSurface& plate) {
  const std::size_t n = loop.vertices.size();
  const std::size_t count = std::min(n, static_cast<std::size_t>(std::max(budget, 3)));
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t i = k * n / count;
    const Point p = loop.points[i];
    const Point normal = options.fitted_normals
                             ? fitted_normal(mesh, loop.vertices[i], options.normal_fit_max_angle)
                             : surface_normal(mesh, loop.vertices[i]);
    if (options.tangent_constraints && normal.norm() > 0.0) {
      Handle(Geom_Plane) tangent_plane =
          new Geom_Plane(to_gp(p), gp_Dir(normal[0], normal[1], normal[2]));
      plate.Add(Handle(GeomPlate_PointConstraint)(
          new GeomPlate_PointConstraint(0.0, 0.0, tangent_plane, 1, tolerance, 0.01)));
    } else {
      plate.Add(
          Handle(GeomPlate_PointConstraint)(new GeomPlate_PointConstraint(to_gp(p), 0, tolerance)));
    }
  }
  return count;
}

/// Interior points of the region inside `loops[0]` and outside the others, on a square grid
/// of `spacing`, each at least half a spacing from every loop edge.
std::vector<Point2> interior_grid(const std::vector<std::vector<Point2>>& loops, double spacing) {
  std::vector<std::vector<Point2d>> polygons;
  for (const auto& loop : loops) {
    polygons.emplace_back();
    for (const Point2& p : loop)
      polygons.back().push_back({p[0], p[1]});
  }
  auto inside = [&](std::size_t l, const Point2& p) {
    return inside_polygon_2d(polygons[l], {p[0], p[1]});
  };
  // Not core's distance_to_polygon_2d: that one measures along each edge from its other end,
  // and grid points lie exactly half a spacing from axis-aligned edges, where a last-bit
  // difference would move a point in or out of the patch.
  auto distance_to_loop = [](const std::vector<Point2>& loop, const Point2& p) {
    double best = std::numeric_limits<double>::max();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Point2 &a = loop[i], &b = loop[(i + 1) % loop.size()];
      const double dx = b[0] - a[0], dy = b[1] - a[1];
      const double l2 = dx * dx + dy * dy;
      const double t =
          l2 > 0.0 ? std::clamp(((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
      best = std::min(best, std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy));
    }
    return best;
  };
  Point2 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
  Point2 hi{-lo[0], -lo[1]};
  for (const Point2& p : loops[0]) {
    for (int k = 0; k < 2; ++k) {
      lo[k] = std::min(lo[k], p[k]);
      hi[k] = std::max(hi[k], p[k]);
    }
  }
  std::vector<Point2> points;
  if (!(spacing > 0.0))
    return points;
  for (double u = lo[0] + 0.5 * spacing; u < hi[0]; u += spacing) {
    for (double v = lo[1] + 0.5 * spacing; v < hi[1]; v += spacing) {
      const Point2 p{u, v};
      if (!inside(0, p))
        continue;
      bool keep = true;
      for (std::size_t l = 0; l < loops.size() && keep; ++l) {
        keep = distance_to_loop(loops[l], p) >= 0.5 * spacing && (l == 0 || !inside(l, p));
      }
      if (keep)
        points.push_back(p);
    }
  }
  return points;
}

/// The `index`-th point of the loops in order.
const Point2& domain_point(const std::vector<std::vector<Point2>>& loops, std::size_t index) {
  for (const auto& loop : loops) {
    if (index < loop.size())
      return loop[index];
    index -= loop.size();
  }
  return loops.back().back();
}

/// The middles (in the domain) of the triangulation's edges between two boundary vertices
/// that the mesh already joins by an edge other than a loop edge: a triangle on such a chord
/// would give that edge a third face. Each gets a Steiner point, and the domain is
/// triangulated again.
std::vector<Point2> taken_chord_middles(const Mesh& mesh,
                                        const std::vector<std::vector<Point2>>& loops,
                                        const std::vector<VertexHandle>& boundary,
                                        const PolygonTriangulation2d& triangulation) {
  const int n = static_cast<int>(boundary.size());
  auto point = [&](int index) -> const Point2& {
    return domain_point(loops, static_cast<std::size_t>(index));
  };
  std::vector<Point2> middles;
  std::set<std::pair<int, int>> seen;
  for (const auto& t : triangulation.triangles) {
    for (int k = 0; k < 3; ++k) {
      const int a = std::min(t[k], t[(k + 1) % 3]), b = std::max(t[k], t[(k + 1) % 3]);
      if (b >= n || !seen.insert({a, b}).second)
        continue;
      const HalfedgeHandle h = mesh.find_halfedge(boundary[static_cast<std::size_t>(a)],
                                                  boundary[static_cast<std::size_t>(b)]);
      if (!h.is_valid())
        continue;
      // A loop edge (both ends are this hole's boundary vertices, so a boundary edge between
      // them is one of its loops' edges).
      if (mesh.is_boundary(h) || mesh.is_boundary(mesh.opposite_halfedge_handle(h)))
        continue;
      middles.push_back({0.5 * (point(a)[0] + point(b)[0]), 0.5 * (point(a)[1] + point(b)[1])});
    }
  }
  return middles;
}

std::string failure_reason(const PolygonTriangulation2d& triangulation) {
  switch (triangulation.failure) {
    case TriangulationFailure::ShortLoop:
      return "a loop with fewer than three points";
    case TriangulationFailure::SharedPoint:
      return "two boundary points project onto one point of the plate's parameter plane";
    case TriangulationFailure::SelfIntersection:
      return "the boundary folds over in the plate's parameter plane (the hole's "
             "least-squares plane): " +
             triangulation.detail;
    case TriangulationFailure::ForeignPoint:
      return "the triangulation needed a point that is not on the boundary";
    case TriangulationFailure::NoTriangle:
      return "no triangle inside the boundary";
    case TriangulationFailure::None:
      break;
  }
  return "";
}

/// Fills one hole (its loop and islands) in `mesh`; returns the reason it stayed open, or
/// "" when closed.
std::string fill_hole(Mesh& mesh, const std::vector<HoleLoop>& loops, const HoleGroup& group,
                      const OcctFillOptions& options, HoleReport& report) {
  std::vector<const HoleLoop*> parts{&loops[group.outer]};
  for (std::size_t i : group.islands)
    parts.push_back(&loops[i]);
  std::vector<Point> all_points;
  double length = 0.0;
  std::size_t edges = 0;
  for (const HoleLoop* loop : parts) {
    all_points.insert(all_points.end(), loop->points.begin(), loop->points.end());
    length += loop->length;
    edges += loop->points.size();
  }
  const PlaneFit fit = fit_plane(all_points);
  if (!fit.valid)
    return "the boundary points lie on a line: no plane to start the plate from";
  const double mean_edge = length / static_cast<double>(edges);

  PlateFrame frame;
  // The plane's normal on the side the surrounding surface faces (a boundary loop runs
  // clockwise seen from outside, so its Newell normal points inwards).
  Point normal = fit.plane.normal;
  if (OpenMesh::dot(normal, loops[group.outer].newell) > 0.0)
    normal = -normal;
  frame.axes = gp_Ax3(to_gp(fit.plane.point), gp_Dir(normal[0], normal[1], normal[2]));
  frame.origin = fit.plane.point;
  frame.normal = normal;
  const gp_Dir x = frame.axes.XDirection(), y = frame.axes.YDirection();
  frame.x = Point(x.X(), x.Y(), x.Z());
  frame.y = Point(y.X(), y.Y(), y.Z());

  // The plate: the hole's plane deformed to meet the boundary constraints.
  const double tolerance = 1e-4 * std::max(loops[group.outer].diameter, mean_edge);
  GeomPlate_BuildPlateSurface plate(options.degree, 10, options.iterations, 1e-5, tolerance);
  plate.LoadInitSurface(new Geom_Plane(frame.axes));
  std::size_t constraints = 0;
  for (const HoleLoop* loop : parts) {
    const int budget = static_cast<int>(std::ceil(options.max_constraints * loop->length / length));
    constraints += add_constraints(mesh, *loop, budget, tolerance, options, plate);
  }
  try {
    plate.Perform();
  } catch (const Standard_Failure& failure) {
    return std::string("the plate surface could not be computed: ") + failure.GetMessageString();
  }
  if (!plate.IsDone())
    return "the plate surface could not be computed";
  Handle(GeomPlate_Surface) surface = plate.Surface();

  // The patch: a constrained Delaunay triangulation of the boundary in the plate's
  // parameters, with interior points on a grid, mapped onto the plate.
  std::vector<std::vector<Point2>> domain;
  std::vector<VertexHandle> boundary;
  for (const HoleLoop* loop : parts) {
    domain.emplace_back();
    for (std::size_t i = 0; i < loop->points.size(); ++i) {
      domain.back().push_back(frame.uv(loop->points[i]));
      boundary.push_back(loop->vertices[i]);
    }
  }
  std::vector<Point2> grid = interior_grid(domain, options.interior_spacing_edges * mean_edge);
  PolygonTriangulation2d triangulation = triangulate_polygon_2d(domain, grid);
  for (int round = 0; triangulation.ok() && round < options.max_chord_split_rounds; ++round) {
    const std::vector<Point2> middles = taken_chord_middles(mesh, domain, boundary, triangulation);
    if (middles.empty())
      break;
    grid.insert(grid.end(), middles.begin(), middles.end());
    triangulation = triangulate_polygon_2d(domain, grid);
  }
  if (!triangulation.ok())
    return failure_reason(triangulation);

  // Orientation: the boundary half-edge from loop point 0 to 1 has no face; the patch's
  // triangle on that edge must run the same way.
  bool flip = false;
  for (const auto& t : triangulation.triangles) {
    for (int k = 0; k < 3; ++k) {
      if ((t[k] == 0 && t[(k + 1) % 3] == 1) || (t[k] == 1 && t[(k + 1) % 3] == 0))
        flip = t[k] == 1;
    }
  }

  std::vector<VertexHandle> handles = boundary;
  for (int index : triangulation.kept_interior) {
    const Point2& p = grid[static_cast<std::size_t>(index)];
    gp_Pnt q;
    try {
      surface->D0(p[0], p[1], q);
    } catch (const Standard_Failure& failure) {
      for (std::size_t i = boundary.size(); i < handles.size(); ++i)
        mesh.delete_vertex(handles[i], false);
      return std::string("the plate surface could not be evaluated: ") + failure.GetMessageString();
    }
    handles.push_back(mesh.add_vertex(Point(q.X(), q.Y(), q.Z())));
  }
  std::vector<FaceHandle> added;
  for (const auto& t : triangulation.triangles) {
    const VertexHandle a = handles[static_cast<std::size_t>(t[0])];
    const VertexHandle b = handles[static_cast<std::size_t>(t[1])];
    const VertexHandle c = handles[static_cast<std::size_t>(t[2])];
    const FaceHandle f = flip ? mesh.add_face(a, c, b) : mesh.add_face(a, b, c);
    if (!f.is_valid()) {
      for (FaceHandle g : added)
        mesh.delete_face(g, false);
      for (std::size_t i = boundary.size(); i < handles.size(); ++i)
        mesh.delete_vertex(handles[i], false);
      return "a facet of the patch would make the mesh non-manifold";
    }
    added.push_back(f);
  }
  report.new_faces = added.size();
  report.new_vertices = handles.size() - boundary.size();
  // How closely the plate meets the hole's boundary (its G0 gap; the patch itself uses the
  // boundary vertices, so this is the step between the boundary and the first interior row).
  double gap = 0.0;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    const Point2& p = domain_point(domain, i);
    gp_Pnt q;
    surface->D0(p[0], p[1], q);
    gap = std::max(gap, (Point(q.X(), q.Y(), q.Z()) - mesh.point(boundary[i])).norm());
  }
  std::ostringstream note;
  note << "plate surface, " << (options.tangent_constraints ? "G0 + G1" : "G0") << " at "
       << constraints << " boundary point(s), meets the boundary within " << gap;
  if (!group.islands.empty())
    note << "; islands " << group.islands.size();
  report.note = note.str();
  return "";
}

}  // namespace

MethodResult fill_holes_occt_plate(const Mesh& holed, const OcctFillOptions& options) {
  const auto start = SteadyClock::now();
  // OpenCASCADE prints to standard output by default; the harness owns it.
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  MethodResult result;
  result.repaired = holed;
  Mesh& mesh = result.repaired;
  std::vector<HoleLoop> loops;
  for (const BoundaryLoop& loop : find_boundary_loops(holed))
    loops.push_back(make_hole_loop(holed, loop));
  const std::vector<HoleGroup> groups = group_islands(loops, options.attach_islands);

  std::size_t closed = 0;
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto hole_start = SteadyClock::now();
    HoleReport report;
    report.hole_index = static_cast<int>(g);
    const HoleLoop& outer = loops[groups[g].outer];
    report.loop_size = outer.points.size();
    report.centroid = outer.centroid;
    const std::string open = fill_hole(mesh, loops, groups[g], options, report);
    report.closed = open.empty();
    if (!report.closed)
      report.note = open;
    report.seconds = seconds_since(hole_start);
    closed += report.closed ? 1 : 0;
    result.holes.push_back(std::move(report));
  }
  mesh.garbage_collection();
  result.status = closed == groups.size() ? MethodStatus::Ok
                  : closed > 0            ? MethodStatus::Partial
                                          : MethodStatus::Failed;
  if (result.status != MethodStatus::Ok) {
    result.message = std::to_string(groups.size() - closed) + " of " +
                     std::to_string(groups.size()) + " hole(s) left open (see the hole notes)";
  }
  result.phases.push_back({"N-sided plate filling", seconds_since(start)});
  return result;
}

MethodOptions OcctFillMethod::options() const {
  return MethodOptions()
      .add("max_constraints", options_.max_constraints)
      .add("tangent_constraints", options_.tangent_constraints)
      .add("fitted_normals", options_.fitted_normals)
      .add("normal_fit_max_angle", options_.normal_fit_max_angle)
      .add("degree", options_.degree)
      .add("iterations", options_.iterations)
      .add("interior_spacing_edges", options_.interior_spacing_edges)
      .add("max_chord_split_rounds", options_.max_chord_split_rounds)
      .add("attach_islands", options_.attach_islands);
}

}  // namespace holebench
