#include "generators/brep/polyhedron.h"

#include "core/mesh_builder.h"
#include "generators/brep/planar_triangulation.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace holebench::generators::brep {
namespace {

using Key = std::array<double, 3>;

Key key_of(const Point& p) {
  return {p[0], p[1], p[2]};
}

// Twice the signed area of a loop about `normal` (Newell's method).
Point newell(const std::vector<Point>& loop) {
  Point sum(0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    sum += OpenMesh::cross(loop[i], loop[(i + 1) % loop.size()]);
  return sum;
}

// Shared vertices of the tessellation, keyed by exact coordinates.
class VertexPool {
 public:
  explicit VertexPool(TriangleSoup& soup) : soup_(soup) {}
  int at(const Point& p) {
    auto [it, inserted] = index_.emplace(key_of(p), static_cast<int>(soup_.points.size()));
    if (inserted)
      soup_.points.push_back(p);
    return it->second;
  }

 private:
  TriangleSoup& soup_;
  std::map<Key, int> index_;
};

// The points of edge a -> b, b excluded, with n - 1 interior points of an n-part uniform
// subdivision. Interior points are computed from the lexicographically smaller end point,
// so both faces along an edge get bit-identical points.
void subdivide(const Point& a, const Point& b, double spacing, std::vector<Point>& out) {
  const int parts = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing - 1e-9)));
  const bool forward = key_of(a) < key_of(b);
  const Point& lo = forward ? a : b;
  const Point& hi = forward ? b : a;
  out.push_back(a);
  for (int i = 1; i < parts; ++i) {
    const int t = forward ? i : parts - i;
    out.push_back(lo + (hi - lo) * (static_cast<double>(t) / parts));
  }
}

double segment_distance(const std::array<double, 2>& p, const std::array<double, 2>& a,
                        const std::array<double, 2>& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double length2 = dx * dx + dy * dy;
  double t = length2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  const double ex = a[0] + t * dx - p[0], ey = a[1] + t * dy - p[1];
  return std::sqrt(ex * ex + ey * ey);
}

// Even-odd rule over all loops.
bool inside(const std::array<double, 2>& p, const PlanarDomain& domain) {
  bool in = false;
  for (const auto& loop : domain.loops) {
    for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
      const auto& a = domain.points[loop[i]];
      const auto& b = domain.points[loop[j]];
      if ((a[1] > p[1]) != (b[1] > p[1]) &&
          p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0])
        in = !in;
    }
  }
  return in;
}

void tessellate_face(const PlanarFace& face, int region_id, const TessellationOptions& options,
                     VertexPool& pool, TriangleSoup& soup) {
  const Point normal = face_normal(face);
  const Point origin = face.outer[0];
  Point u = face.outer[1] - face.outer[0];
  u /= u.norm();
  const Point v = OpenMesh::cross(normal, u);

  PlanarDomain domain;
  std::vector<Point> points3;
  auto add = [&](const Point& p) {
    points3.push_back(p);
    const Point d = p - origin;
    domain.points.push_back({OpenMesh::dot(d, u), OpenMesh::dot(d, v)});
    return static_cast<int>(points3.size()) - 1;
  };
  for (int l = 0; l < face.loop_count(); ++l) {
    const auto& loop = face.loop(l);
    std::vector<Point> subdivided;
    for (std::size_t i = 0; i < loop.size(); ++i)
      subdivide(loop[i], loop[(i + 1) % loop.size()], options.spacing, subdivided);
    std::vector<int> indices;
    for (const Point& p : subdivided)
      indices.push_back(add(p));
    domain.loops.push_back(std::move(indices));
  }

  // A hexagonal lattice (no four co-circular points, so the Delaunay triangulation is
  // unique) anchored at the outer loop's first point.
  double min_x = 0.0, max_x = 0.0, min_y = 0.0, max_y = 0.0;
  for (const auto& p : domain.points) {
    min_x = std::min(min_x, p[0]);
    max_x = std::max(max_x, p[0]);
    min_y = std::min(min_y, p[1]);
    max_y = std::max(max_y, p[1]);
  }
  const double h = options.spacing;
  const double row = h * std::sqrt(3.0) / 2.0;
  const double clearance = options.boundary_clearance * h;
  for (int j = static_cast<int>(std::floor(min_y / row)); j * row <= max_y; ++j) {
    const double shift = (j % 2 != 0) ? 0.5 * h : 0.0;
    for (int i = static_cast<int>(std::floor(min_x / h)) - 1; i * h + shift <= max_x; ++i) {
      const std::array<double, 2> p{i * h + shift, j * row};
      if (!inside(p, domain))
        continue;
      bool clear = true;
      for (const auto& loop : domain.loops) {
        for (std::size_t k = 0; k < loop.size() && clear; ++k) {
          clear = segment_distance(p, domain.points[loop[k]],
                                   domain.points[loop[(k + 1) % loop.size()]]) > clearance;
        }
      }
      if (clear)
        add(origin + u * p[0] + v * p[1]);
    }
  }

  for (const auto& triangle : triangulate_domain(domain)) {
    soup.triangles.push_back({pool.at(points3[triangle[0]]), pool.at(points3[triangle[1]]),
                              pool.at(points3[triangle[2]])});
    soup.regions.push_back(region_id);
  }
}

}  // namespace

Point face_normal(const PlanarFace& face) {
  const Point n = newell(face.outer);
  return n / n.norm();
}

double face_area(const PlanarFace& face) {
  const Point normal = face_normal(face);
  double area = 0.0;
  for (int l = 0; l < face.loop_count(); ++l)
    area += 0.5 * OpenMesh::dot(newell(face.loop(l)), normal);
  return area;
}

PolyhedronTopology::PolyhedronTopology(const Polyhedron& polyhedron) : polyhedron_(polyhedron) {
  for (int f = 0; f < static_cast<int>(polyhedron.faces.size()); ++f) {
    const auto& face = polyhedron.faces[f];
    normals_.push_back(face_normal(face));
    for (int l = 0; l < face.loop_count(); ++l) {
      const auto& loop = face.loop(l);
      for (int i = 0; i < static_cast<int>(loop.size()); ++i) {
        const auto key = std::make_pair(key_of(loop[i]), key_of(loop[(i + 1) % loop.size()]));
        if (!edges_.emplace(key, LoopEdge{f, l, i}).second)
          throw std::logic_error("polyhedron: a directed edge is used twice");
      }
    }
  }
}

std::optional<LoopEdge> PolyhedronTopology::find(const Point& from, const Point& to) const {
  auto it = edges_.find(std::make_pair(key_of(from), key_of(to)));
  if (it == edges_.end())
    return std::nullopt;
  return it->second;
}

const Point& PolyhedronTopology::from(const LoopEdge& edge) const {
  return polyhedron_.faces[edge.face].loop(edge.loop)[edge.index];
}

const Point& PolyhedronTopology::to(const LoopEdge& edge) const {
  const auto& loop = polyhedron_.faces[edge.face].loop(edge.loop);
  return loop[(edge.index + 1) % loop.size()];
}

LoopEdge PolyhedronTopology::next(const LoopEdge& edge) const {
  const auto size = static_cast<int>(polyhedron_.faces[edge.face].loop(edge.loop).size());
  return {edge.face, edge.loop, (edge.index + 1) % size};
}

LoopEdge PolyhedronTopology::previous(const LoopEdge& edge) const {
  const auto size = static_cast<int>(polyhedron_.faces[edge.face].loop(edge.loop).size());
  return {edge.face, edge.loop, (edge.index + size - 1) % size};
}

std::optional<LoopEdge> PolyhedronTopology::twin(const LoopEdge& edge) const {
  return find(to(edge), from(edge));
}

Convexity PolyhedronTopology::convexity(const LoopEdge& edge) const {
  const auto other = twin(edge);
  if (!other)
    throw std::logic_error("polyhedron: convexity of an edge without twin");
  const Point axis = to(edge) - from(edge);
  const double sine =
      OpenMesh::dot(OpenMesh::cross(normals_[edge.face], normals_[other->face]), axis);
  return sine > 0.0 ? Convexity::Convex : Convexity::Reflex;
}

std::vector<Point> PolyhedronTopology::vertices() const {
  std::vector<Point> points;
  for (const auto& [key, edge] : edges_) {
    if (points.empty() || key_of(points.back()) != key.first)
      points.push_back(from(edge));
  }
  return points;
}

std::vector<LoopEdge> PolyhedronTopology::edges_around(const Point& vertex) const {
  // The first outgoing edge in key order; then rotate: the face holding P -> R, where
  // R -> P is the current face's edge into the vertex, is the next one counter-clockwise.
  auto it =
      edges_.lower_bound(std::make_pair(key_of(vertex), Key{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}));
  if (it == edges_.end() || it->first.first != key_of(vertex))
    throw std::logic_error("polyhedron: not a vertex");
  const LoopEdge start = it->second;
  std::vector<LoopEdge> faces;
  LoopEdge edge = start;
  for (std::size_t guard = 0; guard <= polyhedron_.faces.size() * 4; ++guard) {
    faces.push_back(edge);
    const auto next_edge = twin(previous(edge));
    if (!next_edge)
      throw std::logic_error("polyhedron: vertex on an open boundary");
    edge = *next_edge;
    if (edge.face == start.face && edge.loop == start.loop && edge.index == start.index)
      return faces;
  }
  throw std::logic_error("polyhedron: non-manifold vertex");
}

Mesh tessellate(const Polyhedron& polyhedron, const TessellationOptions& options) {
  TriangleSoup soup;
  VertexPool pool(soup);
  for (int f = 0; f < static_cast<int>(polyhedron.faces.size()); ++f)
    tessellate_face(polyhedron.faces[f], f, options, pool, soup);
  return build_mesh(soup, BuildOptions{"brep tessellation"});
}

Polyhedron scaled(const Polyhedron& polyhedron, double factor) {
  Polyhedron result = polyhedron;
  for (auto& face : result.faces) {
    for (auto& p : face.outer)
      p *= factor;
    for (auto& loop : face.inner) {
      for (auto& p : loop)
        p *= factor;
    }
  }
  return result;
}

}  // namespace holebench::generators::brep
