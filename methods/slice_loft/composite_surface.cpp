#include "methods/slice_loft/composite_surface.h"

#include "core/plane_fit.h"
#include "methods/slice_loft/discrete_curvature.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <set>
#include <unordered_map>

namespace holebench::slice_loft {
namespace {

// ---- portions -------------------------------------------------------------------------

BoundaryNode vertex_node(const Mesh& mesh, VertexHandle v) {
  return {v, -1, mesh.point(v)};
}
BoundaryNode feature_node(const MissingFeatures& features, int index) {
  return {VertexHandle(), index, features.points[index]};
}

int island_region(const Mesh& mesh, const Contour& island, const std::vector<int>& face_region) {
  std::map<int, int> votes;
  for (auto h : island.loop.halfedges)
    ++votes[face_region[mesh.face_handle(mesh.opposite_halfedge_handle(h)).idx()]];
  int best = kNoRegion, count = -1;
  for (auto [region, n] : votes) {
    if (n > count) {
      best = region;
      count = n;
    }
  }
  return best;
}

// ---- slicing --------------------------------------------------------------------------

// A connected piece of a slice: points in order, and whether each end lies on a boundary
// edge of the mesh (a slice point on the hole or island boundary).
struct SlicePiece {
  std::vector<Point> points;
  bool front_on_boundary = false, back_on_boundary = false;
  int front_edge = -1, back_edge = -1;  ///< the mesh edges the ends lie on
};

// The slice of `faces` by the plane dot(p - origin, d) = u.
std::vector<SlicePiece> slice(const Mesh& mesh, const std::vector<FaceHandle>& faces,
                              const Point& origin, const Point& d, double u) {
  std::unordered_map<int, Point> edge_point;
  std::unordered_map<int, std::vector<int>> edge_segments;
  std::vector<std::array<int, 2>> segments;
  auto side = [&](VertexHandle v) { return OpenMesh::dot(mesh.point(v) - origin, d) - u; };
  for (auto f : faces) {
    std::array<int, 2> crossing{-1, -1};
    int count = 0;
    for (auto h : mesh.fh_range(f)) {
      const double sa = side(h.from()), sb = side(h.to());
      if ((sa >= 0.0) == (sb >= 0.0))
        continue;
      const int e = h.edge().idx();
      if (!edge_point.count(e)) {
        const Point& a = mesh.point(h.from());
        edge_point[e] = a + (mesh.point(h.to()) - a) * (sa / (sa - sb));
      }
      if (count < 2)
        crossing[count] = e;
      ++count;
    }
    if (count != 2)
      continue;
    const int s = static_cast<int>(segments.size());
    segments.push_back(crossing);
    edge_segments[crossing[0]].push_back(s);
    edge_segments[crossing[1]].push_back(s);
  }
  std::vector<char> used(segments.size(), 0);
  std::vector<SlicePiece> pieces;
  // Walk chains from their ends (edges used by one segment); closed loops are skipped.
  std::vector<int> ends;
  for (const auto& [e, list] : edge_segments) {
    if (list.size() == 1)
      ends.push_back(e);
  }
  std::sort(ends.begin(), ends.end());  // deterministic
  for (int start : ends) {
    const int first = edge_segments[start][0];
    if (used[first])
      continue;
    SlicePiece piece;
    piece.front_on_boundary = mesh.is_boundary(mesh.edge_handle(start));
    piece.front_edge = start;
    piece.points.push_back(edge_point[start]);
    int edge = start, segment = first;
    while (segment >= 0 && !used[segment]) {
      used[segment] = 1;
      edge = segments[segment][0] == edge ? segments[segment][1] : segments[segment][0];
      piece.points.push_back(edge_point[edge]);
      int next = -1;
      for (int s : edge_segments[edge]) {
        if (!used[s])
          next = s;
      }
      segment = next;
    }
    piece.back_on_boundary = mesh.is_boundary(mesh.edge_handle(edge));
    piece.back_edge = edge;
    if (piece.points.size() >= 2)
      pieces.push_back(std::move(piece));
  }
  return pieces;
}

// Where the polylines cross the plane dot(p - origin, d) = u.
std::vector<Point> crossings(const std::vector<std::vector<Point>>& polylines, const Point& origin,
                             const Point& d, double u) {
  std::vector<Point> points;
  for (const auto& polyline : polylines) {
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
      const double sa = OpenMesh::dot(polyline[i] - origin, d) - u;
      const double sb = OpenMesh::dot(polyline[i + 1] - origin, d) - u;
      if ((sa >= 0.0) != (sb >= 0.0))
        points.push_back(polyline[i] + (polyline[i + 1] - polyline[i]) * (sa / (sa - sb)));
    }
  }
  return points;
}

struct Frame {
  Point origin, d, e, n;
};

// The portion's frame: n the mean normal of its triangles, d the slicing direction in the
// plane normal to n (the major axis of the boundary there, or the paper's longer box edge).
Frame portion_frame(const Mesh& mesh, const std::vector<FaceHandle>& faces,
                    const std::vector<Point>& boundary, SlicingDirection direction) {
  Frame frame;
  Point n(0, 0, 0);
  for (auto f : faces)
    n += face_normal(mesh, f) * face_area(mesh, f);
  const PlaneFit fit = fit_plane(boundary);
  if (n.norm() < 1e-12)
    n = fit.valid ? fit.plane.normal : Point(0, 0, 1);
  frame.n = n.normalized();
  Point centroid(0, 0, 0);
  for (const Point& p : boundary)
    centroid += p;
  frame.origin = centroid / static_cast<double>(boundary.size());
  const Point helper = std::abs(frame.n[0]) < 0.9 ? Point(1, 0, 0) : Point(0, 1, 0);
  const Point a = OpenMesh::cross(frame.n, helper).normalized();
  const Point b = OpenMesh::cross(frame.n, a);
  double xx = 0, xy = 0, yy = 0;
  for (const Point& p : boundary) {
    const double x = OpenMesh::dot(p - frame.origin, a), y = OpenMesh::dot(p - frame.origin, b);
    xx += x * x;
    xy += x * y;
    yy += y * y;
  }
  const double angle = 0.5 * std::atan2(2.0 * xy, xx - yy);  // major axis
  frame.d = (a * std::cos(angle) + b * std::sin(angle)).normalized();
  if (direction == SlicingDirection::LongerBoxEdge) {
    // Section 4.4: "along the longer edge of the bounding box" of the portion: the model's
    // axis along which the portion's box is longest (among the axes not along n), in the
    // plane normal to n.
    Point low = boundary.front(), high = boundary.front();
    for (const Point& p : boundary) {
      low.minimize(p);
      high.maximize(p);
    }
    double longest = -1.0;
    for (int k = 0; k < 3; ++k) {
      Point axis(0, 0, 0);
      axis[k] = 1.0;
      const Point in_plane = axis - frame.n * OpenMesh::dot(axis, frame.n);
      if (in_plane.norm() < 0.5)
        continue;
      if (high[k] - low[k] > longest) {
        longest = high[k] - low[k];
        frame.d = in_plane.normalized();
      }
    }
  }
  frame.e = OpenMesh::cross(frame.n, frame.d);
  return frame;
}

// ---- section curves ------------------------------------------------------------------

// Builds the section curve of one slice from its pieces (ordered by increasing w, each
// running in that direction), tracing across the gaps with curvature continuity (eqs. 1-3).
class SectionTracer {
 public:
  SectionTracer(const LoftedPatch& patch, const CompositeSurfaceOptions& options, double edge,
                double w_min, double w_max, std::vector<Point> targets)
      : patch_(patch),
        options_(options),
        w_min_(w_min),
        w_max_(w_max),
        margin_(2.0 * edge),
        baseline_(options.baseline_edges * edge),
        targets_(std::move(targets)) {
    trace_.step = options.step_edges * edge;
    trace_.max_turn_rad = options.max_turn_degrees * M_PI / 180.0;
    trace_.max_steps =
        static_cast<int>(std::ceil((w_max - w_min + 2.0 * margin_) / trace_.step)) + 8;
  }

  // The project's option (SectionExtent::InfluencingArea): the left extension, every piece
  // with the traced gaps between them (hole, hole to island, ...), the right extension, each
  // end extended beyond the portion by a margin (or bent onto a missing edge's crossing).
  std::vector<Point> over_influencing_area(const std::vector<SlicePiece>& kept,
                                           std::vector<Point>& traced) const {
    std::vector<Point> points = extend_end(kept.front(), false, w_min_ - margin_, traced);
    std::reverse(points.begin(), points.end());
    for (std::size_t k = 0; k < kept.size(); ++k) {
      points.insert(points.end(), kept[k].points.begin(), kept[k].points.end());
      if (k + 1 == kept.size())
        break;
      const auto gap = trace_gap(kept[k], kept[k + 1]);
      traced.insert(traced.end(), gap.begin(), gap.end());
      points.insert(points.end(), gap.begin(), gap.end());
    }
    const auto right_end = extend_end(kept.back(), true, w_max_ + margin_, traced);
    points.insert(points.end(), right_end.begin(), right_end.end());
    return points;
  }

  // The paper's section (SectionExtent::HoleBoundary, section 4.4): from a slice point on the
  // hole's boundary to the other end of the slice on the boundary, original (the next piece's
  // end) or regenerated (a missing edge's crossing: a partial slice, figure 12a), through the
  // islands' slices on the way (hole to island, island to island, island to hole). A slice
  // that crosses the portion more than once gives one curve per crossing; the longest is the
  // section (the loft takes one curve per slice).
  std::vector<Point> between_boundaries(const std::vector<SlicePiece>& kept,
                                        const std::function<bool(int)>& island_edge,
                                        std::vector<Point>& traced) const {
    std::vector<Point> best, current, current_traced;
    std::size_t best_traced = 0;
    std::vector<Point> best_traced_points;
    auto close_curve = [&]() {
      if (current.size() >= 2 && current_traced.size() >= best_traced) {
        best_traced = current_traced.size();
        best_traced_points = current_traced;
        best = current;
      }
      current.clear();
      current_traced.clear();
    };
    // A partial slice at the left end: the hole (or its portion) lies beyond the first piece.
    if (kept.front().front_on_boundary) {
      std::vector<Point> beyond = extend_end(kept.front(), false, w_min_, current_traced);
      std::reverse(beyond.begin(), beyond.end());
      current = beyond;
    }
    for (std::size_t k = 0; k < kept.size(); ++k) {
      const SlicePiece& piece = kept[k];
      if (!current.empty()) {
        // Arrived at this piece's front across a gap: an island's slice is part of the
        // section; any other piece ends it.
        if (island_edge(piece.front_edge) && island_edge(piece.back_edge)) {
          current.insert(current.end(), piece.points.begin(), piece.points.end());
        } else {
          current.push_back(piece.points.front());
          close_curve();
        }
      }
      if (!piece.back_on_boundary) {
        close_curve();
        continue;
      }
      if (current.empty())
        current.push_back(piece.points.back());
      const double w_end = patch_.w_of(piece.points.back());
      const double w_next = k + 1 < kept.size() ? patch_.w_of(kept[k + 1].points.front()) : 1e300;
      const Point* target = nearest_target(w_end, true);
      if (target && patch_.w_of(*target) < w_next) {
        // A partial slice: the portion ends on a regenerated boundary (a missing edge).
        const auto to_target = extend_end(piece, true, w_max_, current_traced);
        current.insert(current.end(), to_target.begin(), to_target.end());
        close_curve();
      } else if (k + 1 < kept.size() && kept[k + 1].front_on_boundary) {
        const auto gap = trace_gap(piece, kept[k + 1]);
        current_traced.insert(current_traced.end(), gap.begin(), gap.end());
        current.insert(current.end(), gap.begin(), gap.end());
      } else {
        // Nothing of the region beyond this end inside the influencing area: traced until it
        // leaves the hole's extent.
        const auto beyond = extend_end(piece, true, w_max_, current_traced);
        current.insert(current.end(), beyond.begin(), beyond.end());
        close_curve();
      }
    }
    close_curve();
    if (best.empty())
      return {};
    traced.insert(traced.end(), best_traced_points.begin(), best_traced_points.end());
    return best;
  }

 private:
  const LoftedPatch& patch_;
  const CompositeSurfaceOptions& options_;
  double w_min_, w_max_, margin_, baseline_;
  std::vector<Point> targets_;
  TraceOptions trace_;

  // Traces from the end of a piece away from it: `outward` runs from that end inwards.
  std::vector<Point> trace_from(const std::vector<Point>& outward, double w_stop,
                                bool increasing) const {
    const BackPoints back = back_points(outward, baseline_);
    if (!back.valid)
      return std::vector<Point>{outward.front()};
    return trace_curvature_continuous(back.q2, back.q1, back.q0, trace_, [&](const Point& p) {
      return increasing ? patch_.w_of(p) > w_stop : patch_.w_of(p) < w_stop;
    });
  }

  // The missing-edge crossing nearest beyond `w_end` on the given side, or nullptr.
  const Point* nearest_target(double w_end, bool right) const {
    const Point* target = nullptr;
    for (const Point& t : targets_) {
      const double wt = patch_.w_of(t);
      if ((right ? wt > w_end : wt < w_end) &&
          (!target || std::abs(wt - w_end) < std::abs(patch_.w_of(*target) - w_end)))
        target = &t;
    }
    return target;
  }

  // One-sided extension at an end of a piece, bent through a missing-edge crossing, else
  // traced until `limit`; the points beyond the piece's end, going away from it.
  std::vector<Point> extend_end(const SlicePiece& piece, bool right, double limit,
                                std::vector<Point>& traced) const {
    std::vector<Point> outward = piece.points;
    if (right)
      std::reverse(outward.begin(), outward.end());
    const double w_end = patch_.w_of(outward.front());
    const Point* target = nearest_target(w_end, right);
    std::vector<Point> beyond;
    if (target) {
      const double wt = patch_.w_of(*target);
      const auto from_end = trace_from(outward, right ? wt + margin_ : wt - margin_, right);
      beyond = bend_to(from_end, *target, trace_.step);
      traced.insert(traced.end(), beyond.begin(), beyond.end());
      beyond.push_back(*target);
    } else if (right ? w_end < limit : w_end > limit) {
      beyond = trace_from(outward, limit, right);
      beyond.erase(beyond.begin());
      traced.insert(traced.end(), beyond.begin(), beyond.end());
    }
    return beyond;
  }

  // The points inside the gap between two pieces: traced from the left piece's end and bent
  // onto the right one's (the paper's one end), or traced from both and blended.
  std::vector<Point> trace_gap(const SlicePiece& left_piece, const SlicePiece& right_piece) const {
    std::vector<Point> left(left_piece.points.rbegin(), left_piece.points.rend());
    const std::vector<Point>& right = right_piece.points;
    const double wl = patch_.w_of(left.front()), wr = patch_.w_of(right.front());
    const auto from_left = trace_from(left, wr + margin_, true);
    if (options_.tracing == GapTracing::OneEnd)
      return bend_to(from_left, right.front(), trace_.step);
    const auto from_right = trace_from(right, wl - margin_, false);
    return bridge(from_left, from_right, trace_.step);
  }
};

}  // namespace

bool decomposed_by_features(const Hole& hole, const MissingFeatures& features) {
  const std::size_t m = hole.segments.size();
  return m >= 2 && features.edges.size() == m;
}

std::vector<Portion> hole_portions(const Mesh& mesh, const std::vector<Contour>& contours,
                                   const Hole& hole, const MissingFeatures& features,
                                   const std::vector<int>& face_region) {
  std::vector<Portion> portions;
  const std::size_t m = hole.segments.size();
  if (!decomposed_by_features(hole, features)) {
    Portion portion;
    portion.region = m == 1 ? hole.segments[0].region : kNoRegion;
    for (auto v : contours[hole.contour].vertices)
      portion.boundary.push_back(vertex_node(mesh, v));
    portions.push_back(std::move(portion));
  } else {
    for (std::size_t i = 0; i < m; ++i) {
      const Segment& segment = hole.segments[i];
      const std::size_t next = (i + 1) % m;
      Portion portion;
      portion.region = segment.region;
      for (auto v : segment.vertices)
        portion.boundary.push_back(vertex_node(mesh, v));
      // Back from the segment's end to its start through the missing features.
      std::vector<Point> path_next{mesh.point(segment.end)}, path_this{mesh.point(segment.start)};
      for (int index : features.edges[next].points) {
        portion.boundary.push_back(feature_node(features, index));
        path_next.push_back(features.points[index]);
      }
      if (features.corner >= 0) {
        const auto& own = features.edges[i].points;
        for (auto it = own.rbegin(); it != own.rend(); ++it) {
          if (*it != features.corner)
            portion.boundary.push_back(feature_node(features, *it));
        }
        for (int index : own)
          path_this.push_back(features.points[index]);
        portion.missing_edges = {path_next, path_this};
      } else {
        path_next.push_back(mesh.point(segment.start));
        portion.missing_edges = {path_next};
      }
      portions.push_back(std::move(portion));
    }
  }
  for (int index : hole.islands) {
    std::vector<BoundaryNode> island;
    for (auto v : contours[index].vertices)
      island.push_back(vertex_node(mesh, v));
    const int region = island_region(mesh, contours[index], face_region);
    std::size_t owner = 0;
    for (std::size_t p = 0; p < portions.size(); ++p) {
      if (portions[p].region == region)
        owner = p;
    }
    portions[owner].islands.push_back(std::move(island));
  }
  return portions;
}

LoftedPatch loft_portion(const Mesh& mesh, const Hole& hole, const Portion& portion,
                         const std::vector<int>& face_region,
                         const CompositeSurfaceOptions& options) {
  LoftedPatch patch;
  std::vector<FaceHandle> faces;
  for (auto f : hole.influencing) {
    if (portion.region == kNoRegion || face_region[f.idx()] == portion.region)
      faces.push_back(f);
  }
  if (faces.empty()) {
    patch.error = "no influencing triangle in the portion's region";
    return patch;
  }
  std::vector<Point> boundary;
  for (const auto& node : portion.boundary)
    boundary.push_back(node.position);
  const Frame frame = portion_frame(mesh, faces, boundary, options.direction);
  patch.origin = frame.origin;
  patch.d = frame.d;
  patch.e = frame.e;
  patch.n = frame.n;

  double u_min = 1e300, u_max = -1e300, w_min = 1e300, w_max = -1e300;
  auto extend = [&](const Point& p) {
    u_min = std::min(u_min, patch.u_of(p));
    u_max = std::max(u_max, patch.u_of(p));
    w_min = std::min(w_min, patch.w_of(p));
    w_max = std::max(w_max, patch.w_of(p));
  };
  for (const Point& p : boundary)
    extend(p);
  for (const auto& island : portion.islands) {
    for (const auto& node : island)
      extend(node.position);
  }
  const double edge = hole.mean_edge_length;
  const double extent = u_max - u_min;
  if (!(extent > 0.0)) {
    patch.error = "a portion without extent";
    return patch;
  }
  const double spacing = std::min(extent / options.slices, options.max_slice_spacing_edges * edge);
  const int count = std::max(1, static_cast<int>(std::ceil(extent / spacing)));
  const double h = extent / count;

  // Whether a slice point's edge is an island's boundary edge (section 4.4: a section runs
  // from the hole's boundary to an island's and on through the island's slice).
  std::set<int> island_vertices;
  for (const auto& island : portion.islands) {
    for (const auto& node : island) {
      if (node.vertex.is_valid())
        island_vertices.insert(node.vertex.idx());
    }
  }
  auto island_edge = [&](int e) {
    if (e < 0)
      return false;
    const auto h = mesh.halfedge_handle(mesh.edge_handle(e), 0);
    return island_vertices.count(mesh.from_vertex_handle(h).idx()) > 0 &&
           island_vertices.count(mesh.to_vertex_handle(h).idx()) > 0;
  };

  for (int j = -options.extra_slices; j < count + options.extra_slices; ++j) {
    Section section;
    section.u = u_min + (j + 0.5) * h;
    // Slice pieces as 3D polylines ordered by increasing w; overlapping pieces (a second
    // sheet of the region) are dropped, longest first kept.
    std::vector<SlicePiece> pieces = slice(mesh, faces, patch.origin, patch.d, section.u);
    for (auto& piece : pieces) {
      if (patch.w_of(piece.points.front()) > patch.w_of(piece.points.back())) {
        std::reverse(piece.points.begin(), piece.points.end());
        std::swap(piece.front_on_boundary, piece.back_on_boundary);
      }
    }
    std::sort(pieces.begin(), pieces.end(), [](const SlicePiece& a, const SlicePiece& b) {
      return polyline_length(a.points) > polyline_length(b.points);
    });
    std::vector<SlicePiece> kept;
    for (auto& piece : pieces) {
      const double lo = patch.w_of(piece.points.front()), hi = patch.w_of(piece.points.back());
      bool overlaps = false;
      for (const auto& k : kept) {
        overlaps =
            overlaps || (lo < patch.w_of(k.points.back()) && hi > patch.w_of(k.points.front()));
      }
      if (!overlaps)
        kept.push_back(std::move(piece));
    }
    if (kept.empty())
      continue;
    std::sort(kept.begin(), kept.end(), [&](const SlicePiece& a, const SlicePiece& b) {
      return patch.w_of(a.points.front()) < patch.w_of(b.points.front());
    });
    SectionTracer tracer(patch, options, edge, w_min, w_max,
                         crossings(portion.missing_edges, patch.origin, patch.d, section.u));
    std::vector<Point> points = options.extent == SectionExtent::InfluencingArea
                                    ? tracer.over_influencing_area(kept, section.traced)
                                    : tracer.between_boundaries(kept, island_edge, section.traced);
    section.points = std::move(points);
    if (section.points.size() >= 2)
      patch.sections.push_back(std::move(section));
  }
  if (patch.sections.size() < 2) {
    patch.error = "fewer than two section curves";
    return patch;
  }
  std::vector<SectionPolyline> polylines;
  for (const auto& section : patch.sections)
    polylines.push_back({section.u, section.points});
  LoftOptions loft;
  loft.sample_spacing = options.section_sample_edges * edge;
  patch.surface = LoftedSurface::loft(patch.origin, patch.d, polylines, loft);
  if (!patch.surface.ok()) {
    patch.error = patch.surface.error();
    return patch;
  }
  patch.ok = true;
  return patch;
}

}  // namespace holebench::slice_loft
