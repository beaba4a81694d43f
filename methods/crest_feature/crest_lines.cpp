// The crest_feature method's CGAL translation unit for jet fitting and ridges.
#include "methods/crest_feature/crest_lines.h"

#include "methods/crest_feature/sharp_creases.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Monge_via_jet_fitting.h>
#include <CGAL/Ridges.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <map>

namespace holebench::crest_feature {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using Vector3 = Kernel::Vector_3;
using GraphTraits = boost::graph_traits<Mesh>;
using VertexDescriptor = GraphTraits::vertex_descriptor;
using Monge = CGAL::Monge_via_jet_fitting<Kernel>;

using ScalarMap = std::map<VertexDescriptor, double>;
using VectorMap = std::map<VertexDescriptor, Vector3>;
using ScalarPmap = boost::associative_property_map<ScalarMap>;
using VectorPmap = boost::associative_property_map<VectorMap>;

Point3 to_cgal(const Point& p) {
  return Point3(p[0], p[1], p[2]);
}

// The area-weighted outward normal at a vertex.
Point vertex_normal(const Mesh& mesh, VertexHandle v) {
  Point n(0, 0, 0);
  for (auto f : mesh.vf_range(v)) {
    auto it = mesh.cfv_begin(f);
    const Point a = mesh.point(*it++), b = mesh.point(*it++), c = mesh.point(*it);
    n += OpenMesh::cross(b - a, c - a);
  }
  const double length = n.norm();
  return length > 0 ? n / length : n;
}

// The vertex and its rings of neighbours, grown until there are enough points.
std::vector<VertexHandle> neighbourhood(const Mesh& mesh, VertexHandle v,
                                        const CrestLineOptions& options) {
  std::vector<VertexHandle> result{v};
  std::map<int, bool> visited{{v.idx(), true}};
  std::vector<VertexHandle> front{v};
  for (int ring = 1; ring <= options.max_rings; ++ring) {
    std::vector<VertexHandle> next;
    for (auto u : front) {
      for (auto w : mesh.vv_range(u)) {
        if (visited.emplace(w.idx(), true).second) {
          next.push_back(w);
          result.push_back(w);
        }
      }
    }
    front = std::move(next);
    if (ring >= options.min_rings && static_cast<int>(result.size()) >= options.min_fit_points)
      break;
    if (front.empty())
      break;
  }
  return result;
}

// Whether each vertex lies within `rings` rings of a boundary vertex (every vertex when
// rings <= 0 or the mesh has no boundary).
std::vector<char> band_around_boundaries(const Mesh& mesh, int rings) {
  std::vector<char> in_band(mesh.n_vertices(), rings <= 0 ? 1 : 0);
  if (rings <= 0)
    return in_band;
  std::vector<VertexHandle> front;
  for (auto v : mesh.vertices()) {
    if (mesh.is_boundary(v)) {
      in_band[v.idx()] = 1;
      front.push_back(v);
    }
  }
  if (front.empty())
    return std::vector<char>(mesh.n_vertices(), 1);
  for (int ring = 1; ring <= rings && !front.empty(); ++ring) {
    std::vector<VertexHandle> next;
    for (auto u : front) {
      for (auto w : mesh.vv_range(u)) {
        if (!in_band[w.idx()]) {
          in_band[w.idx()] = 1;
          next.push_back(w);
        }
      }
    }
    front = std::move(next);
  }
  return in_band;
}

// The faces whose three vertices lie in the band, as a mesh of their own; `origin` maps each
// of its vertices to the input's.
Mesh band_mesh(const Mesh& mesh, const std::vector<char>& in_band,
               std::vector<VertexHandle>& origin) {
  Mesh band;
  std::vector<VertexHandle> copy(mesh.n_vertices());
  for (auto f : mesh.faces()) {
    std::array<VertexHandle, 3> v;
    int i = 0;
    bool inside = true;
    for (auto u : mesh.fv_range(f)) {
      inside = inside && in_band[u.idx()];
      v[i++ % 3] = u;
    }
    if (!inside)
      continue;
    std::array<VertexHandle, 3> w;
    for (int k = 0; k < 3; ++k) {
      if (!copy[v[k].idx()].is_valid()) {
        copy[v[k].idx()] = band.add_vertex(mesh.point(v[k]));
        origin.push_back(v[k]);
      }
      w[k] = copy[v[k].idx()];
    }
    band.add_face(w[0], w[1], w[2]);  // a face OpenMesh refuses (non-manifold) is left out
  }
  return band;
}

// The fields CGAL's ridge approximation reads, per vertex: the principal curvatures k1, k2
// and directions d1, d2, the extremality coefficients b0, b3 and p1, p2 of the jet fit.
struct JetFields {
  ScalarMap k1, k2, b0, b3, p1, p2;
  VectorMap d1, d2;
};

// The jets fitted at the vertices of the band (in_band); elsewhere, and where the fit fails,
// no curvature, so no ridge crosses an edge at an unfitted vertex.
JetFields fit_jets(const Mesh& mesh, const std::vector<char>& in_band,
                   const CrestLineOptions& options) {
  JetFields f;
  const int degree = std::max(3, options.jet_degree);
  const std::size_t needed = static_cast<std::size_t>((degree + 1) * (degree + 2) / 2);
  for (auto v : mesh.vertices()) {
    // Defaults: no curvature, so no ridge crosses an edge at an unfitted vertex.
    f.k1[v] = f.k2[v] = f.b0[v] = f.b3[v] = f.p1[v] = f.p2[v] = 0.0;
    f.d1[v] = Vector3(1, 0, 0);
    f.d2[v] = Vector3(0, 1, 0);
    if (mesh.is_isolated(v) || !in_band[v.idx()])
      continue;
    std::vector<Point3> points;
    for (auto u : neighbourhood(mesh, v, options))
      points.push_back(to_cgal(mesh.point(u)));
    if (points.size() < needed)
      continue;
    Monge::Monge_form form;
    try {
      Monge fitter;
      form = fitter(points.begin(), points.end(), static_cast<std::size_t>(degree),
                    static_cast<std::size_t>(degree));
    } catch (...) {
      continue;
    }
    // The paper's convention: a convex crease is a ridge with k_max > 0. The Monge form's z
    // axis points along the given normal and a convex surface bends away from the outward
    // normal, so the fit is oriented along the inward normal.
    const Point n = -vertex_normal(mesh, v);
    form.comply_wrt_given_normal(Vector3(n[0], n[1], n[2]));
    const auto& c = form.coefficients();
    if (c.size() < 6)
      continue;
    f.d1[v] = form.maximal_principal_direction();
    f.d2[v] = form.minimal_principal_direction();
    f.k1[v] = c[0];
    f.k2[v] = c[1];
    f.b0[v] = c[2];
    f.b3[v] = c[5];
    if (c.size() >= 11) {
      f.p1[v] = 3 * c[3] * c[3] + (c[0] - c[1]) * (c[6] - 3 * c[0] * c[0] * c[0]);
      f.p2[v] = 3 * c[4] * c[4] + (c[1] - c[0]) * (c[10] - 3 * c[1] * c[1] * c[1]);
    }
  }
  return f;
}

// The fields of the mesh's vertices read at the band's (`origin`: each band vertex's vertex
// of the mesh).
JetFields on_band(JetFields& f, const Mesh& band, const std::vector<VertexHandle>& origin) {
  JetFields b;
  for (auto v : band.vertices()) {
    const VertexHandle o = origin[v.idx()];
    b.k1[v] = f.k1[o];
    b.k2[v] = f.k2[o];
    b.b0[v] = f.b0[o];
    b.b3[v] = f.b3[o];
    b.p1[v] = f.p1[o];
    b.p2[v] = f.p2[o];
    b.d1[v] = f.d1[o];
    b.d2[v] = f.d2[o];
  }
  return b;
}

// CGAL's ridge tracing assumes that every regular triangle is crossed on 0 or 2 edges; a
// crossing is a sign change of (d_p . d_q) b_p b_q, so that holds where no b and no dot
// product of principal directions is exactly 0. Planar parts (exact zeros, axis-aligned
// directions) break it: keep every b away from 0 and tilt every direction by a tiny generic
// amount, then check every triangle and give up (false: no crest lines) rather than let CGAL
// read an unset crossing.
bool make_generic_for_tracing(const Mesh& traced, JetFields& f) {
  const Vector3 tilt(0.3141592653589793e-7, 0.2718281828459045e-7, 0.1414213562373095e-7);
  for (auto v : traced.vertices()) {
    for (double* b : {&f.b0[v], &f.b3[v]}) {
      if (std::abs(*b) < 1e-100)
        *b = 1e-100;
    }
    f.d1[v] = f.d1[v] + tilt;
    f.d2[v] = f.d2[v] - tilt;
  }
  auto& d1 = f.d1;
  for (auto face : traced.faces()) {
    std::array<VertexDescriptor, 3> v;
    int i = 0;
    for (auto u : traced.fv_range(face))
      v[i++ % 3] = u;
    const double regular = (d1[v[0]] * d1[v[1]]) * (d1[v[0]] * d1[v[2]]) * (d1[v[1]] * d1[v[2]]);
    if (regular < 0)
      continue;  // CGAL skips it
    for (const ScalarMap* b : {&f.b0, &f.b3}) {
      int crossed = 0;
      for (int k = 0; k < 3; ++k) {
        const auto p = v[k], q = v[(k + 1) % 3];
        crossed += (d1[p] * d1[q]) * b->at(p) * b->at(q) < 0 ? 1 : 0;
      }
      if (regular == 0.0 || crossed % 2 == 1)
        return false;
    }
  }
  return true;
}

// The crest ridges CGAL traces on `traced`, each kept (in `result.lines`) where its sign and
// strength say it is a crest line, counted as weak where only its strength fails.
void keep_crest_ridges(const Mesh& traced, JetFields& f, const CrestLineOptions& options,
                       CrestLines& result) {
  using Ridges = CGAL::Ridge_approximation<Mesh, ScalarPmap, VectorPmap>;
  ScalarMap &k1 = f.k1, &k2 = f.k2;
  ScalarPmap k1m(f.k1), k2m(f.k2), b0m(f.b0), b3m(f.b3), p1m(f.p1), p2m(f.p2);
  VectorPmap d1m(f.d1), d2m(f.d2);
  Ridges ridges(traced, k1m, k2m, b0m, b3m, d1m, d2m, p1m, p2m);
  std::vector<Ridges::Ridge_line*> found;
  ridges.compute_crest_ridges(std::back_inserter(found), CGAL::Ridge_order_3);

  const double min_curvature =
      options.min_mean_curvature_times_edge / std::max(result.mean_edge_length, 1e-300);
  for (auto* line : found) {
    CrestLine crest;
    const auto type = line->line_type();
    // Crest ridges are elliptic (k_max has a maximum across the line, eq. 1; k_min a
    // minimum, eq. 2) with |k_max| > |k_min| (max crest) or |k_min| > |k_max| (min crest);
    // the signs are checked below.
    const bool ridge = type == CGAL::MAX_CREST_RIDGE;
    const bool ravine = type == CGAL::MIN_CREST_RIDGE;
    double k_max_sum = 0.0, k_min_sum = 0.0;
    for (const auto& [h, coord] : *line->line()) {
      const auto p = traced.from_vertex_handle(h), q = traced.to_vertex_handle(h);
      crest.points.push_back(traced.point(p) * coord + traced.point(q) * (1.0 - coord));
      k_max_sum += coord * k1[p] + (1.0 - coord) * k1[q];
      k_min_sum += coord * k2[p] + (1.0 - coord) * k2[q];
    }
    const double n = static_cast<double>(std::max<std::size_t>(1, crest.points.size()));
    const double k_max = k_max_sum / n, k_min = k_min_sum / n;
    double length = 0.0;
    for (std::size_t i = 1; i < crest.points.size(); ++i)
      length += (crest.points[i] - crest.points[i - 1]).norm();
    crest.mean_curvature = length > 0 ? line->strength() / length : 0.0;
    const bool ridge_ok = ridge && k_max > std::abs(k_min);
    const bool ravine_ok = ravine && k_min < -std::abs(k_max);
    crest.type = ridge_ok ? CrestType::Ridge : CrestType::Ravine;
    const bool strong = crest.mean_curvature >= min_curvature &&
                        static_cast<int>(crest.points.size()) > options.min_segments;
    if ((ridge_ok || ravine_ok) && strong) {
      result.lines.push_back(std::move(crest));
    } else if (ridge_ok || ravine_ok) {
      ++result.dropped_weak;
    }
    delete line;
  }
}

}  // namespace

CrestLines detect_crest_lines(const Mesh& mesh, const CrestLineOptions& options) {
  CrestLines result;
  double total = 0.0;
  for (auto e : mesh.edges())
    total += mesh.calc_edge_length(e);
  result.mean_edge_length = mesh.n_edges() > 0 ? total / static_cast<double>(mesh.n_edges()) : 0;
  if (mesh.n_faces() == 0)
    return result;

  // Only a band of rings around the holes is fitted and traced: the crest lines the method
  // uses are those that reach a hole's boundary.
  const std::vector<char> in_band = band_around_boundaries(mesh, options.band_rings);
  JetFields fields = fit_jets(mesh, in_band, options);
  std::vector<VertexHandle> origin;
  const bool whole = options.band_rings <= 0;
  const Mesh band = whole ? Mesh() : band_mesh(mesh, in_band, origin);
  const Mesh& traced = whole ? mesh : band;
  if (!whole)
    fields = on_band(fields, band, origin);
  if (!make_generic_for_tracing(traced, fields)) {
    result.skipped = true;
    return result;
  }
  keep_crest_ridges(traced, fields, options, result);
  // Sharp creases (sharp_creases.h): the crease itself is the crest line, and the fitted
  // ridges beside it are dropped.
  std::vector<CrestLine> creases =
      trace_sharp_creases(mesh, in_band, result.mean_edge_length, options);
  drop_crest_points_near(result.lines, creases,
                         options.sharp_crease_clearance_edges * result.mean_edge_length,
                         options.min_segments);
  result.lines.insert(result.lines.end(), std::make_move_iterator(creases.begin()),
                      std::make_move_iterator(creases.end()));
  return result;
}

}  // namespace holebench::crest_feature
