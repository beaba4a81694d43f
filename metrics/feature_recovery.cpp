#include "metrics/feature_recovery.h"

#include "core/geometry.h"
#include "core/nearest_segment.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"
#include "metrics/growing_box.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <unordered_map>

namespace holebench {
namespace {

std::vector<Point> sample_polyline(const std::vector<Point>& polyline, double spacing) {
  std::vector<Point> samples;
  if (polyline.empty())
    return samples;
  samples.push_back(polyline.front());
  for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point& a = polyline[i];
    const Point& b = polyline[i + 1];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / spacing)));
    for (int s = 1; s <= steps; ++s)
      samples.push_back(a + (b - a) * (static_cast<double>(s) / steps));
  }
  return samples;
}

// The distance from `corner` to the nearest vertex of `mesh` from index `first` on.
double nearest_vertex_distance(const Mesh& mesh, const Point& corner, std::size_t first) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = first; i < mesh.n_vertices(); ++i) {
    const VertexHandle v(static_cast<int>(i));
    if (!mesh.status(v).deleted())
      best = std::min(best, (mesh.point(v) - corner).norm());
  }
  return best;
}

// The box of a polyline grown by `margin` on every side.
GrowingBox polyline_box(const std::vector<Point>& polyline, double margin) {
  GrowingBox box;
  for (const Point& p : polyline)
    box.add(p);
  const Point grow(margin, margin, margin);
  box.lo -= grow;
  box.hi += grow;
  return box;
}

bool segment_meets(const GrowingBox& box, const Point& a, const Point& b) {
  Point lo = a, hi = a;
  lo.minimize(b);
  hi.maximize(b);
  bool overlaps = true;
  for (int k = 0; k < 3; ++k)
    overlaps = overlaps && lo[k] <= box.hi[k] && hi[k] >= box.lo[k];
  return overlaps;
}

// The repaired mesh's sharp edges, as segments, from its whole feature analysis.
class WholeMeshSharpEdges {
 public:
  WholeMeshSharpEdges(const Mesh& repaired, const FeatureOptions& options) {
    const FeatureAnalysis analysis = analyse_features(repaired, options);
    for (auto e : repaired.edges()) {
      if (analysis.edge_is_sharp[e.idx()])
        sharp_.push_back({repaired.point(e.v0()), repaired.point(e.v1())});
    }
  }
  std::vector<SegmentEnds> meeting(const GrowingBox& box) const {
    std::vector<SegmentEnds> near;
    for (const auto& s : sharp_) {
      if (segment_meets(box, s.a, s.b))
        near.push_back(s);
    }
    return near;
  }

 private:
  std::vector<SegmentEnds> sharp_;
};

// The repaired mesh's sharp edges near a box, from the input's regions: segment_regions makes
// an edge sharp where its two faces lie in different regions, regions being the faces joined
// across edges whose dihedral angle is at most the threshold. With every input face kept, the
// repair's regions are the input's joined across the edges of its other faces (kept-kept
// edges are the input's, with the same faces and angle), so a union-find over the input's
// regions and the other faces, built from those faces' edges, names each face's region.
class SharpEdgesFromInput {
 public:
  SharpEdgesFromInput(const Mesh& repaired, const FeatureOptions& options,
                      const FeatureRecoveryShortcuts& known)
      : repaired_(repaired), known_(known) {
    const double threshold = options.segmentation.sharp_angle_degrees * M_PI / 180.0;
    for (int f : known.kept->repaired_faces_not_kept) {
      const FaceHandle face(f);
      if (repaired.status(face).deleted())
        continue;
      for (auto h : repaired.fh_range(face)) {
        const EdgeHandle e = repaired.edge_handle(h);
        if (repaired.is_boundary(e) || std::abs(signed_dihedral_angle(repaired, e)) > threshold)
          continue;
        join(node(face), node(repaired.face_handle(repaired.opposite_halfedge_handle(h))));
      }
    }
  }

  // The sharp edges that meet `box` among those within `radius` of the polyline, and perhaps
  // others: what WholeMeshSharpEdges::meeting() gives, less edges farther than `radius` from
  // every point of the polyline, which no sample weighs where `radius` is the larger of the
  // search radius and the tolerance (a nearest distance past both counts as none). The faces are
  // found about each of the polyline's segments (a ball about its midpoint holding the segment
  // grown by `radius`: a face with a point within `radius` of the segment), not in the
  // box's enclosing ball, which on a long diagonal edge holds much more of the model.
  std::vector<SegmentEnds> meeting(const GrowingBox& box, const std::vector<Point>& polyline,
                                   double radius) const {
    std::vector<SegmentEnds> near;
    std::vector<int> edges;
    const auto add_faces_within = [&](const Point& centre, double reach) {
      for (int f : known_.repaired_scene->faces_within(centre, reach * (1.0 + 1e-9))) {
        if (repaired_.status(FaceHandle(f)).deleted())
          continue;
        for (auto h : repaired_.fh_range(FaceHandle(f)))
          edges.push_back(repaired_.edge_handle(h).idx());
      }
    };
    if (polyline.size() == 1)
      add_faces_within(polyline.front(), radius);
    for (std::size_t i = 0; i + 1 < polyline.size(); ++i) {
      const Point& a = polyline[i];
      const Point& b = polyline[i + 1];
      add_faces_within((a + b) * 0.5, 0.5 * (b - a).norm() + radius);
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    for (int index : edges) {
      const EdgeHandle e(index);
      if (repaired_.status(e).deleted() || repaired_.is_boundary(e))
        continue;
      const HalfedgeHandle h = repaired_.halfedge_handle(e, 0);
      const FaceHandle f0 = repaired_.face_handle(h);
      const FaceHandle f1 = repaired_.face_handle(repaired_.opposite_halfedge_handle(h));
      if (root(node(f0)) == root(node(f1)))
        continue;
      const auto smart = OpenMesh::make_smart(e, &repaired_);  // the whole analysis's ends
      const Point a = repaired_.point(smart.v0());
      const Point b = repaired_.point(smart.v1());
      if (segment_meets(box, a, b))
        near.push_back({a, b});
    }
    return near;
  }

 private:
  // A kept face's node is its input face's region; another face's, its own (offset past
  // every region id).
  long node(FaceHandle f) const {
    const int input_face = known_.kept->input_face_of_repaired[f.idx()];
    if (input_face >= 0)
      return (*known_.input_face_regions)[input_face];
    return static_cast<long>(known_.input_face_regions->size()) + f.idx();
  }
  long root(long n) const {
    auto it = parent_.find(n);
    while (it != parent_.end() && it->second != n) {
      n = it->second;
      it = parent_.find(n);
    }
    return n;
  }
  void join(long a, long b) {
    a = root(a);
    b = root(b);
    if (a != b)
      parent_[std::max(a, b)] = std::min(a, b);
  }

  const Mesh& repaired_;
  const FeatureRecoveryShortcuts& known_;
  std::unordered_map<long, long> parent_;  // nodes not in it are their own roots
};

// Whether the shortcut to the sharp edges holds: every input face kept, a scene, regions.
bool sharp_edges_from_input(const FeatureOptions& options, const FeatureRecoveryShortcuts& known) {
  if (options.regions_from_mesh || !known.input_face_regions || !known.kept ||
      !known.repaired_scene)
    return false;
  return known.kept->every_input_face_kept();
}

}  // namespace

std::vector<double> input_corner_distances(const Case& c) {
  std::vector<double> distances;
  for (const auto& hole : c.holes) {
    for (const Point& corner : hole.missing_corners)
      distances.push_back(nearest_vertex_distance(c.input, corner, 0));
  }
  return distances;
}

FeatureRecovery feature_recovery(const Case& c, const Mesh& repaired,
                                 const embree::TriangleScene& complete_scene,
                                 const FeatureRecoveryOptions& options,
                                 const FeatureRecoveryShortcuts& shortcuts) {
  const std::vector<double>* input_corner_distances = shortcuts.input_corner_distances;
  FeatureRecovery result;

  // The input's vertices (where known) and the repair's own after them: the minimum is the
  // same as over all the repair's vertices.
  std::size_t corner = 0;
  for (const auto& hole : c.holes) {
    for (const Point& point : hole.missing_corners) {
      result.corner_errors.push_back(
          input_corner_distances
              ? std::min((*input_corner_distances)[corner],
                         nearest_vertex_distance(repaired, point, c.input.n_vertices()))
              : nearest_vertex_distance(repaired, point, 0));
      ++corner;
    }
  }

  bool any_missing_edge = false;
  for (const auto& hole : c.holes)
    any_missing_edge = any_missing_edge || !hole.missing_edges.empty();
  if (any_missing_edge) {
    std::optional<WholeMeshSharpEdges> whole;
    std::optional<SharpEdgesFromInput> from_input;
    if (sharp_edges_from_input(options.features, shortcuts))
      from_input.emplace(repaired, options.features, shortcuts);
    else
      whole.emplace(repaired, options.features);
    for (const auto& hole : c.holes) {
      for (const auto& polyline : hole.missing_edges) {
        MissingEdgeRecovery edge;
        const auto samples = sample_polyline(polyline, options.edge_sample_spacing);
        // Only sharp edges that can be within the search radius of the polyline.
        const GrowingBox box = polyline_box(polyline, options.edge_search_radius);
        // A sample weighs its nearest sharp edge only within the tolerance or the radius.
        const double reach = std::max(options.edge_search_radius, options.edge_tolerance);
        const NearestSegment near(from_input ? from_input->meeting(box, polyline, reach)
                                             : whole->meeting(box));
        std::size_t covered = 0;
        bool all_near = !samples.empty();
        double farthest = 0.0;
        for (const Point& p : samples) {
          const double best = near.distance(p);
          if (best <= options.edge_tolerance)
            ++covered;
          if (best <= options.edge_search_radius)
            farthest = std::max(farthest, best);
          else
            all_near = false;
        }
        edge.covered_fraction =
            samples.empty() ? 0.0 : static_cast<double>(covered) / samples.size();
        edge.present = edge.covered_fraction >= 0.5;
        if (all_near)
          edge.distance = farthest;
        result.edges.push_back(edge);
      }
    }
  }

  double area_sum = 0.0, weighted = 0.0, largest = 0.0;
  std::vector<int> found_new_faces;
  for (int index : new_face_indices(repaired, shortcuts.new_faces, found_new_faces)) {
    const FaceHandle f(index);
    const double area = face_area(repaired, f);
    if (!(area > 0.0))
      continue;
    const double angle = normal_cone_angle(complete_scene, face_centroid(repaired, f),
                                           face_normal(repaired, f), options.normal_cone)
                             .smallest_deg;
    area_sum += area;
    weighted += area * angle;
    largest = std::max(largest, angle);
  }
  if (area_sum > 0.0) {
    result.normal_deviation_mean_deg = weighted / area_sum;
    result.normal_deviation_max_deg = largest;
  }
  return result;
}

}  // namespace holebench
