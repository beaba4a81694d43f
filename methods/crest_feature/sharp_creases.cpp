#include "methods/crest_feature/sharp_creases.h"

#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace holebench::crest_feature {
namespace {

constexpr double kDegree = M_PI / 180.0;

double point_segment(const Point& p, const Point& a, const Point& b) {
  const Point d = b - a;
  const double c = OpenMesh::dot(d, d);
  const double t = c > 0 ? std::clamp(OpenMesh::dot(p - a, d) / c, 0.0, 1.0) : 0.0;
  return (p - (a + d * t)).norm();
}

}  // namespace

std::vector<CrestLine> trace_sharp_creases(const Mesh& mesh, const std::vector<char>& in_band,
                                           double mean_edge_length,
                                           const CrestLineOptions& options) {
  std::vector<CrestLine> result;
  if (!(options.sharp_crease_angle_degrees < 180.0))
    return result;
  const double threshold = options.sharp_crease_angle_degrees * kDegree;
  std::vector<double> angle(mesh.n_edges(), 0.0);  // signed; 0 where not sharp
  std::vector<std::vector<EdgeHandle>> at(mesh.n_vertices());
  for (auto e : mesh.edges()) {
    if (mesh.is_boundary(e) || !in_band[e.v0().idx()] || !in_band[e.v1().idx()])
      continue;
    const double a = signed_dihedral_angle(mesh, e);
    if (!(std::abs(a) > threshold))
      continue;
    angle[e.idx()] = a;
    at[e.v0().idx()].push_back(e);
    at[e.v1().idx()].push_back(e);
  }
  auto other = [&](EdgeHandle e, VertexHandle v) { return e.v0() == v ? e.v1() : e.v0(); };
  // Whether a chain arriving at v along `in` goes on along v's other sharp edge: v has exactly
  // two, is no boundary vertex, and the crease keeps its convexity and does not bend.
  auto next_edge = [&](VertexHandle v, EdgeHandle in) -> EdgeHandle {
    const auto& edges = at[v.idx()];
    if (edges.size() != 2 || mesh.is_boundary(v))
      return EdgeHandle();
    const EdgeHandle out = edges[0] == in ? edges[1] : edges[0];
    if ((angle[in.idx()] > 0) != (angle[out.idx()] > 0))
      return EdgeHandle();
    const Point d_in = mesh.point(v) - mesh.point(other(in, v));
    const Point d_out = mesh.point(other(out, v)) - mesh.point(v);
    const double c = OpenMesh::dot(d_in, d_out) / (d_in.norm() * d_out.norm());
    if (!(std::acos(std::clamp(c, -1.0, 1.0)) <= options.sharp_crease_bend_degrees * kDegree))
      return EdgeHandle();
    return out;
  };
  std::vector<char> visited(mesh.n_edges(), 0);
  for (auto e : mesh.edges()) {
    if (angle[e.idx()] == 0.0 || visited[e.idx()])
      continue;
    visited[e.idx()] = 1;
    // Walk from e both ways; `back` then `front` hold the vertices beyond e's ends.
    std::vector<VertexHandle> sides[2];
    std::vector<EdgeHandle> edges{e};
    bool stops_smoothly[2] = {true, true};  // ended where the crease fades, not at a corner
    for (int side = 0; side < 2; ++side) {
      VertexHandle v = side == 0 ? e.v0() : e.v1();
      EdgeHandle in = e;
      for (;;) {
        const EdgeHandle out = next_edge(v, in);
        if (!out.is_valid() || visited[out.idx()]) {
          // A corner, a bend or a change of convexity is no run-out end; a boundary vertex
          // (the hole) or the crease's fading is.
          stops_smoothly[side] = mesh.is_boundary(v) || at[v.idx()].size() == 1;
          break;
        }
        visited[out.idx()] = 1;
        edges.push_back(out);
        v = other(out, v);
        sides[side].push_back(v);
        in = out;
      }
    }
    CrestLine line;
    std::vector<VertexHandle> chain(sides[0].rbegin(), sides[0].rend());
    chain.push_back(e.v0());
    chain.push_back(e.v1());
    chain.insert(chain.end(), sides[1].begin(), sides[1].end());
    // A crease between a hole and a corner near it is short: one that reaches a boundary
    // vertex is kept whatever its length.
    const bool reaches_boundary = mesh.is_boundary(chain.front()) || mesh.is_boundary(chain.back());
    if (static_cast<int>(chain.size()) <= options.min_segments && !reaches_boundary)
      continue;
    double sum = 0.0;
    for (auto edge : edges)
      sum += angle[edge.idx()];
    line.type = sum > 0 ? CrestType::Ridge : CrestType::Ravine;
    for (auto v : chain)
      line.points.push_back(mesh.point(v));
    line.mean_curvature =
        std::abs(sum) / static_cast<double>(edges.size()) / std::max(mean_edge_length, 1e-300);
    line.runs_out = {stops_smoothly[0], stops_smoothly[1]};
    result.push_back(std::move(line));
  }
  return result;
}

void drop_crest_points_near(std::vector<CrestLine>& lines, const std::vector<CrestLine>& creases,
                            double clearance, int min_segments) {
  if (creases.empty() || !(clearance > 0.0))
    return;
  // Bounding box of each crease, grown by the clearance, for a quick reject.
  struct Box {
    Point lo, hi;
  };
  std::vector<Box> boxes;
  for (const auto& c : creases) {
    Box b{c.points.front(), c.points.front()};
    for (const Point& p : c.points) {
      b.lo.minimize(p);
      b.hi.maximize(p);
    }
    const Point margin(clearance, clearance, clearance);
    boxes.push_back({b.lo - margin, b.hi + margin});
  }
  auto near = [&](const Point& p) {
    for (std::size_t i = 0; i < creases.size(); ++i) {
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside = inside && p[k] >= boxes[i].lo[k] && p[k] <= boxes[i].hi[k];
      if (!inside)
        continue;
      const auto& q = creases[i].points;
      for (std::size_t j = 0; j + 1 < q.size(); ++j) {
        if (point_segment(p, q[j], q[j + 1]) <= clearance)
          return true;
      }
    }
    return false;
  };
  std::vector<CrestLine> kept;
  for (const auto& line : lines) {
    // An end made by the cut lies beside a crease: it is no run-out end.
    CrestLine run{line.type, {}, line.mean_curvature, {line.runs_out[0], false}};
    auto flush = [&](bool at_line_end) {
      run.runs_out[1] = at_line_end && line.runs_out[1];
      if (static_cast<int>(run.points.size()) > min_segments)
        kept.push_back(run);
      run.points.clear();
      run.runs_out[0] = false;
    };
    for (const Point& p : line.points) {
      if (near(p))
        flush(false);
      else
        run.points.push_back(p);
    }
    flush(true);
  }
  lines = std::move(kept);
}

}  // namespace holebench::crest_feature
