#include "methods/crest_feature/feature_points.h"

#include "core/geometry.h"
#include "methods/crest_feature/feature_line_interpolation.h"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <tuple>

namespace holebench::crest_feature {
namespace {

constexpr double kDegree = M_PI / 180.0;

Point normalized(const Point& p) {
  const double n = p.norm();
  return n > 0 ? p / n : p;
}

double angle(const Point& a, const Point& b) {
  const double c = OpenMesh::dot(normalized(a), normalized(b));
  return std::acos(std::clamp(c, -1.0, 1.0));
}

int nearest_boundary_index(const Mesh& mesh, const Hole& hole, const Point& p) {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < hole.vertices.size(); ++i) {
    const double d = (mesh.point(hole.vertices[i]) - p).norm();
    if (d < best_distance) {
      best_distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

// Orients `t` into the hole: towards the hole's centroid side at the feature point.
Point into_hole(const Point& t, const Point& at, const Hole& hole) {
  return OpenMesh::dot(t, hole.centroid - at) < 0 ? -t : t;
}

// A candidate feature point: where the end of a crest line meets the boundary.
struct Candidate {
  int loop_index;
  Point tangent;
  int line;
  double weight;  // the line's strength near the hole
  Point position;
  std::optional<double> edge_parameter;  // inside the edge loop_index -> loop_index + 1
};

// Where the ray e + s t (s in [s_min, s_max]) passes a boundary edge nearest: the edge (its
// start's loop index), its parameter u in [0, 1] and the distance; the closest points of the
// ray's line and the segment, clamped to both. Of equally near edges (a ray that crosses the
// boundary, then the far side of a small hole) the first along the ray.
struct Crossing {
  int edge = -1;
  double u = 0.0;
  double distance = std::numeric_limits<double>::infinity();
  double s = 0.0;  // along the ray
};

Crossing nearest_edge_crossing(const Mesh& mesh, const Hole& hole, const Point& e, const Point& t,
                               double s_min, double s_max) {
  Crossing best;
  const int n = static_cast<int>(hole.vertices.size());
  for (int i = 0; i < n; ++i) {
    const Point p = mesh.point(hole.vertices[i]);
    const Point d = mesh.point(hole.vertices[(i + 1) % n]) - p;
    const double c = OpenMesh::dot(d, d);
    if (!(c > 0.0))
      continue;
    const Point r = e - p;
    const double b = OpenMesh::dot(t, d), rt = OpenMesh::dot(t, r), rd = OpenMesh::dot(d, r);
    const double det = c - b * b;  // t is unit
    double u = det > 1e-12 * c ? std::clamp((rd - rt * b) / det, 0.0, 1.0) : 0.5;
    const double s = std::clamp(u * b - rt, s_min, s_max);
    u = std::clamp(OpenMesh::dot(e + t * s - p, d) / c, 0.0, 1.0);
    const double distance = (e + t * s - (p + d * u)).norm();
    const double tie = 1e-9 * std::sqrt(c);
    if (distance < best.distance - tie || (distance <= best.distance + tie && s < best.s))
      best = {i, u, distance, s};
  }
  return best;
}

// Whether the segment p q lies along the line (e, t): both ends within `fraction` of its
// length of the line.
bool along_line(const Point& p, const Point& q, const Point& e, const Point& t, double fraction) {
  const double tolerance = fraction * (q - p).norm();
  auto off = [&](const Point& x) {
    const Point d = x - e;
    return (d - t * OpenMesh::dot(d, t)).norm();
  };
  return off(p) <= tolerance && off(q) <= tolerance;
}

// The feature point where the ray from the crest line's end `e` along `t` crosses the
// boundary (3.4.1): inside the nearest edge, or at its vertex where the crossing lies within
// `edge_snap_fraction` of it; nullopt where no edge comes within `ray_tolerance_edges` a.
// Only loop_index, position and edge_parameter are set.
std::optional<FeaturePoint> edge_candidate(const Mesh& mesh, const Hole& hole, const Point& e,
                                           const Point& t, const FeaturePointOptions& options) {
  const double a = hole.average_edge_length;
  const Crossing x = nearest_edge_crossing(mesh, hole, e, t, -a, options.reach_edges * a);
  if (x.edge < 0 || x.distance > options.ray_tolerance_edges * a)
    return std::nullopt;
  const int n = static_cast<int>(hole.vertices.size());
  FeaturePoint f;
  f.loop_index = x.edge;
  const Point p0 = mesh.point(hole.vertices[x.edge]);
  const Point q0 = mesh.point(hole.vertices[(x.edge + 1) % n]);
  if (along_line(p0, q0, e, t, options.edge_snap_fraction)) {
    // The boundary runs along the line here: no single crossing; the caller walks to the
    // vertex where the line leaves the boundary and enters the hole (last_vertex_along).
    f.loop_index = OpenMesh::dot(q0 - p0, t) < 0 ? (x.edge + 1) % n : x.edge;
  } else if (x.u >= 1.0 - options.edge_snap_fraction)
    f.loop_index = (x.edge + 1) % n;
  else if (x.u > options.edge_snap_fraction)
    f.edge_parameter = x.u;
  const Point p = mesh.point(hole.vertices[x.edge]);
  const Point q = mesh.point(hole.vertices[(x.edge + 1) % n]);
  f.position = f.edge_parameter ? p + (q - p) * x.u : mesh.point(hole.vertices[f.loop_index]);
  return f;
}

// Points of `line` within `radius` of `p`, the point p excluded.
std::vector<Point> line_points_near(const CrestLine& line, const Point& p, double radius) {
  std::vector<Point> near;
  for (const Point& q : line.points) {
    const double d = (q - p).norm();
    if (d <= radius && d > 1e-12 * radius)
      near.push_back(q);
  }
  return near;
}

// The direction of a crest line that runs out at `end`: the principal axis of its points
// near the end (robust to the zigzag of crest points about a crease), oriented from their
// mean towards the end. Zero where the points do not reach far enough from the end.
Point run_out_direction(const std::vector<Point>& near, const Point& end, double min_extent) {
  if (near.size() < 2)
    return Point(0, 0, 0);
  Point mean(0, 0, 0);
  for (const Point& q : near)
    mean += q;
  mean /= static_cast<double>(near.size());
  if ((end - mean).norm() < min_extent)
    return Point(0, 0, 0);
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Point& q : near) {
    const Eigen::Vector3d d(q[0] - mean[0], q[1] - mean[1], q[2] - mean[2]);
    covariance += d * d.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d axis = solver.eigenvectors().col(2);
  Point t(axis[0], axis[1], axis[2]);
  return OpenMesh::dot(t, end - mean) < 0 ? -t : t;
}

// Where the hole's boundary runs along the line (e, t) from loop vertex `index` on (a crease
// whose first edges the hole's boundary follows), the last vertex on it: the line enters the
// hole there. A neighbour is on the line where it lies ahead, within `fraction` of its
// boundary edge's length of the line.
int last_vertex_along(const Mesh& mesh, const Hole& hole, int index, const Point& e, const Point& t,
                      double fraction) {
  const int n = static_cast<int>(hole.vertices.size());
  auto ahead_on_line = [&](int from, int to) {
    const Point p = mesh.point(hole.vertices[from]), q = mesh.point(hole.vertices[to]);
    const Point d = q - e;
    const double s = OpenMesh::dot(d, t);
    return s > OpenMesh::dot(p - e, t) && (d - t * s).norm() <= fraction * (q - p).norm();
  };
  for (int step : {1, n - 1}) {
    if (!ahead_on_line(index, (index + step) % n))
      continue;
    for (int walked = 0; walked < n && ahead_on_line(index, (index + step) % n); ++walked)
      index = (index + step) % n;
    break;
  }
  return index;
}

}  // namespace

Point estimate_tangent(const Mesh& mesh, const Hole& hole, const CrestLines& crest, int loop_index,
                       int preferred, const FeaturePointOptions& options) {
  const Point f = mesh.point(hole.vertices[loop_index]);
  const double radius = options.tangent_radius_edges * hole.average_edge_length;
  int line = preferred;
  if (line < 0) {
    double best = radius;
    for (std::size_t i = 0; i < crest.lines.size(); ++i) {
      for (const Point& q : crest.lines[i].points) {
        const double d = (q - f).norm();
        if (d < best) {
          best = d;
          line = static_cast<int>(i);
        }
      }
    }
  }
  if (line >= 0) {
    const Point t = run_out_direction(line_points_near(crest.lines[line], f, radius), f,
                                      0.5 * hole.average_edge_length);
    if (t.norm() > 0)
      return into_hole(normalized(t), f, hole);
  }
  // No crest line near: the crease between the boundary triangles on either side.
  const int n = static_cast<int>(hole.vertices.size());
  Point before(0, 0, 0), after(0, 0, 0);
  for (int k = 0; k < 3; ++k) {
    const auto h_before = hole.loop.halfedges[(loop_index - 1 - k + 2 * n) % n];
    const auto h_after = hole.loop.halfedges[(loop_index + k) % n];
    before += face_normal(mesh, mesh.opposite_face_handle(h_before));
    after += face_normal(mesh, mesh.opposite_face_handle(h_after));
  }
  Point t = OpenMesh::cross(before, after);
  if (t.norm() < 1e-3 * before.norm() * after.norm())
    t = hole.centroid - f;
  return into_hole(normalized(t), f, hole);
}

HoleFeatures detect_feature_points(const Mesh& mesh, const Hole& hole, const CrestLines& crest,
                                   const FeaturePointOptions& options) {
  const double a = hole.average_edge_length;
  const double reach = options.reach_edges * a;
  std::vector<Candidate> candidates;
  for (std::size_t l = 0; l < crest.lines.size(); ++l) {
    const auto& points = crest.lines[l].points;
    if (points.size() < 2)
      continue;
    for (int end = 0; end < 2; ++end) {
      if (!crest.lines[l].runs_out[end])
        continue;
      const Point e = end == 0 ? points.front() : points.back();
      // Quick reject: the end is not near this hole.
      if ((e - hole.centroid).norm() > hole.radius + reach)
        continue;
      // The direction in which the line runs out at this end: from its points within the
      // tangent radius to the end point.
      const auto near = line_points_near(crest.lines[l], e, options.tangent_radius_edges * a);
      const Point tangent = run_out_direction(near, e, 0.5 * a);
      if (tangent.norm() == 0.0)
        continue;
      const double weight = crest.lines[l].mean_curvature * static_cast<double>(near.size());
      if (options.on_boundary_edges) {
        // 3.4.1: where the extrapolated line crosses a boundary edge.
        if (auto c = edge_candidate(mesh, hole, e, tangent, options)) {
          if (!c->edge_parameter) {  // at a vertex: where the boundary follows the line, its end
            c->loop_index = last_vertex_along(mesh, hole, c->loop_index, e, tangent,
                                              options.edge_snap_fraction);
            c->position = mesh.point(hole.vertices[c->loop_index]);
          }
          candidates.push_back({c->loop_index, tangent, static_cast<int>(l), weight, c->position,
                                c->edge_parameter});
        }
        continue;
      }
      // The boundary vertex the extrapolated line passes nearest, ahead of the end; of
      // equally near ones the first along the line (a straight crease's ray passes through
      // both of its ends on a small hole).
      int best = -1;
      double best_distance = options.ray_tolerance_edges * a, best_s = 0.0;
      const double tie = 1e-9 * a;
      for (std::size_t i = 0; i < hole.vertices.size(); ++i) {
        const Point d = mesh.point(hole.vertices[i]) - e;
        const double s = OpenMesh::dot(d, tangent);
        if (s < -a || s > reach)
          continue;
        const double off = (d - tangent * std::max(s, 0.0)).norm();
        if (off < best_distance - tie || (best >= 0 && off <= best_distance + tie && s < best_s)) {
          best_distance = off;
          best_s = s;
          best = static_cast<int>(i);
        }
      }
      if (best < 0)
        continue;
      best = last_vertex_along(mesh, hole, best, e, tangent, options.edge_snap_fraction);
      // The tangent into the hole is the line's direction as it runs out.
      candidates.push_back({best, tangent, static_cast<int>(l), weight,
                            mesh.point(hole.vertices[best]), std::nullopt});
    }
  }
  // Merge candidates that are one feature point: the stronger line wins.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& x, const Candidate& y) {
    return std::tie(y.weight, x.loop_index, x.line) < std::tie(x.weight, y.loop_index, y.line);
  });
  HoleFeatures features;
  for (const auto& c : candidates) {
    const Point p = c.position;
    bool merged = false;
    for (const auto& kept : features.points) {
      merged = merged || (kept.position - p).norm() <= options.merge_edges * a;
    }
    if (merged)
      continue;
    features.points.push_back({c.loop_index, p, c.edge_parameter, c.tangent, c.line});
  }
  // Loop order, so that the result does not depend on the strengths' ties.
  std::sort(features.points.begin(), features.points.end(),
            [](const FeaturePoint& x, const FeaturePoint& y) {
              return x.loop_index + x.edge_parameter.value_or(0.0) <
                     y.loop_index + y.edge_parameter.value_or(0.0);
            });

  // The automatic rule (no user): a corner triple first where one fits better than any
  // pair among its points, then pairs, best first.
  const int n = static_cast<int>(features.points.size());
  auto pair_cost = [&](int i, int j) {
    const auto& p = features.points[i];
    const auto& q = features.points[j];
    const Point u = q.position - p.position;
    return std::max(angle(p.tangent, u), angle(q.tangent, -u));
  };
  std::vector<char> used(n, 0);
  if (n >= 3 && n <= 12) {
    double best_cost = options.corner_max_angle_degrees * kDegree;
    std::optional<std::array<int, 3>> best;
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        for (int k = j + 1; k < n; ++k) {
          const std::array<int, 3> triple{i, j, k};
          std::array<Point, 3> at, dir;
          for (int m = 0; m < 3; ++m) {
            at[m] = features.points[triple[m]].position;
            dir[m] = features.points[triple[m]].tangent;
          }
          const auto corner = meeting_point(at, dir);
          if (!corner || (*corner - hole.centroid).norm() > hole.radius)
            continue;
          double cost = 0.0;
          for (int m = 0; m < 3; ++m)
            cost = std::max(cost, angle(dir[m], *corner - at[m]));
          const double pairs = std::min({pair_cost(i, j), pair_cost(i, k), pair_cost(j, k)});
          if (cost < best_cost && cost < pairs) {
            best_cost = cost;
            best = triple;
          }
        }
      }
    }
    if (best) {
      features.corner = best;
      for (int m : *best)
        used[m] = 1;
    }
  }
  std::vector<std::tuple<double, int, int>> pairs;
  for (int i = 0; i < n; ++i) {
    for (int j = i + 1; j < n; ++j) {
      const double cost = pair_cost(i, j);
      if (cost <= options.pair_max_angle_degrees * kDegree)
        pairs.emplace_back(cost, i, j);
    }
  }
  std::sort(pairs.begin(), pairs.end());
  for (const auto& [cost, i, j] : pairs) {
    if (used[i] || used[j])
      continue;
    used[i] = used[j] = 1;
    features.pairs.push_back({i, j});
  }
  return features;
}

HoleFeatures review_feature_points(const Mesh& mesh, const Hole& hole, int hole_index,
                                   const CrestLines& crest, const HoleFeatures& proposed,
                                   User& user, const FeaturePointOptions& options) {
  FeaturePointProposal proposal;
  proposal.hole_index = hole_index;
  proposal.hole_centroid = hole.centroid;
  for (auto v : hole.vertices)
    proposal.boundary.push_back(mesh.point(v));
  for (const auto& p : proposed.points)
    proposal.feature_points.push_back(p.position);
  proposal.pairs = proposed.pairs;
  proposal.corner = proposed.corner;
  proposal.more_corners = proposed.more_corners;
  proposal.corner_links = proposed.corner_links;

  const FeaturePointProposal answer = user.review_feature_points(proposal);

  HoleFeatures result;
  for (const Point& p : answer.feature_points) {
    const int index = nearest_boundary_index(mesh, hole, p);
    // A point the method detected keeps its tangent; a moved or added point takes it from
    // the crest line of the nearest detected point, or from the nearest crest line.
    const FeaturePoint* same = nullptr;
    const FeaturePoint* nearest = nullptr;
    double nearest_distance = options.adopt_crest_line_edges * hole.average_edge_length;
    for (const auto& q : proposed.points) {
      if (q.loop_index == index)
        same = &q;
      const double d = (q.position - mesh.point(hole.vertices[index])).norm();
      if (d <= nearest_distance) {
        nearest_distance = d;
        nearest = &q;
      }
    }
    if (same) {
      result.points.push_back(*same);
      continue;
    }
    FeaturePoint point;
    point.loop_index = index;
    point.position = mesh.point(hole.vertices[index]);
    point.crest_line = nearest ? nearest->crest_line : -1;
    point.tangent = estimate_tangent(mesh, hole, crest, index, point.crest_line, options);
    result.points.push_back(point);
  }
  const int n = static_cast<int>(result.points.size());
  auto valid = [&](int i) { return i >= 0 && i < n; };
  std::set<int> used;
  // A corner's points: valid, distinct and in no earlier corner; those of a further corner
  // also on distinct vertices.
  auto valid_corner = [&](const std::vector<int>& c, bool distinct_vertices) {
    std::set<int> distinct, at;
    for (int i : c) {
      if (!valid(i) || used.count(i))
        return false;
      distinct.insert(i);
      at.insert(result.points[i].loop_index);
    }
    return distinct.size() == c.size() && (!distinct_vertices || at.size() == c.size());
  };
  // The answer's corners in order (triple first), each mapped to its index in the result's.
  std::vector<int> corner_index;
  int kept = 0;
  if (answer.corner) {
    const std::vector<int> c(answer.corner->begin(), answer.corner->end());
    const bool ok = valid_corner(c, false);
    if (ok) {
      result.corner = answer.corner;
      used.insert(c.begin(), c.end());
    }
    corner_index.push_back(ok ? kept++ : -1);
  }
  for (const auto& c : answer.more_corners) {
    const bool ok = c.size() >= 2 && valid_corner(c, true);
    if (ok) {
      result.more_corners.push_back(c);
      used.insert(c.begin(), c.end());
    }
    corner_index.push_back(ok ? kept++ : -1);
  }
  for (const auto& l : answer.corner_links) {
    const int n_corners = static_cast<int>(corner_index.size());
    if (l[0] < 0 || l[1] < 0 || l[0] >= n_corners || l[1] >= n_corners || l[0] == l[1])
      continue;
    const int a = corner_index[l[0]], b = corner_index[l[1]];
    if (a >= 0 && b >= 0)
      result.corner_links.push_back({a, b});
  }
  for (const auto& p : answer.pairs) {
    if (valid(p[0]) && valid(p[1]) && p[0] != p[1] && !used.count(p[0]) && !used.count(p[1]) &&
        result.points[p[0]].loop_index != result.points[p[1]].loop_index) {
      result.pairs.push_back(p);
      used.insert(p[0]);
      used.insert(p[1]);
    }
  }
  return result;
}

std::vector<std::vector<int>> corners(const HoleFeatures& features) {
  std::vector<std::vector<int>> result;
  if (features.corner)
    result.emplace_back(features.corner->begin(), features.corner->end());
  result.insert(result.end(), features.more_corners.begin(), features.more_corners.end());
  return result;
}

}  // namespace holebench::crest_feature
