#include "metrics/surface_distance.h"

#include "metrics/mean_search.h"
#include "metrics/shared_faces.h"

#include <algorithm>

namespace holebench {
namespace {

// Each interval's ends ordered (rounding may cross them by an ulp: the upper end, which
// carries the clamps, is kept) and its value inside.
void settle(DistanceInterval& d) {
  d.lower = std::min(std::max(0.0, d.lower), d.upper);
  d.value = std::clamp(d.value, d.lower, d.upper);
}

// The Hausdorff search's first bounds that `first` holds, and how the search's B differs
// from theirs.
const HausdorffCellBounds* hausdorff_first(const FirstBounds* first) {
  return first ? first->hausdorff : nullptr;
}
const SurfaceChange* change_of(const FirstBounds* first) {
  return first ? &first->change : nullptr;
}

}  // namespace

DistanceSummary distance_summary(const DirectedHausdorff& hausdorff,
                                 const DirectedMeanDistance& mean) {
  DistanceSummary s;
  s.hausdorff = {hausdorff.lower, hausdorff.lower, hausdorff.upper};
  s.rms = {mean.rms_lower, mean.rms, mean.rms_upper};
  s.mean = {mean.mean_lower, mean.mean, mean.mean_upper};
  settle(s.hausdorff);
  // True values: mean <= RMS (Jensen) <= Hausdorff (the largest distance).
  s.rms.upper = std::min(s.rms.upper, s.hausdorff.upper);
  s.rms.lower = std::max(s.rms.lower, s.mean.lower);
  settle(s.rms);
  s.mean.upper = std::min(s.mean.upper, s.rms.upper);
  settle(s.mean);
  s.mean.value = std::min(s.mean.value, s.rms.value);
  return s;
}

DistanceSummary max_of(const DistanceSummary& a, const DistanceSummary& b) {
  const auto larger = [](const DistanceInterval& x, const DistanceInterval& y) {
    return DistanceInterval{std::max(x.lower, y.lower), std::max(x.value, y.value),
                            std::max(x.upper, y.upper)};
  };
  return {larger(a.mean, b.mean), larger(a.rms, b.rms), larger(a.hausdorff, b.hausdorff)};
}

SurfaceDistance surface_distance(const Mesh& a, const embree::TriangleScene& a_scene, const Mesh& b,
                                 const embree::TriangleScene& b_scene,
                                 const SurfaceDistanceOptions& options,
                                 const FirstBounds* a_first_bounds,
                                 const FirstBounds* b_first_bounds,
                                 std::optional<SharedFaces> known_shared,
                                 const SearchStart* a_start, const SearchStart* b_start) {
  // One first pass per direction, shared by the Hausdorff and the mean searches; faces the
  // two meshes share exactly are skipped by both.
  SharedFaces shared = known_shared ? std::move(*known_shared) : shared_faces(a, b);
  VertexDistances a_computed, b_computed;
  if (!a_start)
    a_computed = vertex_distances(a, b_scene, &shared.b_face_of_a,
                                  earlier_vertex_answers(a, a_first_bounds));
  if (!b_start)
    b_computed = vertex_distances(b, a_scene, &shared.a_face_of_b,
                                  earlier_vertex_answers(b, b_first_bounds));
  const VertexDistances& a_vertices = a_start ? a_start->vertices : a_computed;
  const VertexDistances& b_vertices = b_start ? b_start->vertices : b_computed;
  const KnownDistances a_known{&a_vertices, &shared.b_face_of_a,
                               a_start ? &a_start->unshared_faces : nullptr,
                               a_start ? a_start->area : 0.0};
  const KnownDistances b_known{&b_vertices, &shared.a_face_of_b,
                               b_start ? &b_start->unshared_faces : nullptr,
                               b_start ? b_start->area : 0.0};
  SurfaceDistance result;
  result.hausdorff.a_to_b =
      directed_hausdorff(a, b_scene, options.hausdorff, a_known, hausdorff_first(a_first_bounds),
                         change_of(a_first_bounds));
  result.hausdorff.b_to_a =
      directed_hausdorff(b, a_scene, options.hausdorff, b_known, hausdorff_first(b_first_bounds),
                         change_of(b_first_bounds));
  result.a_to_b = directed_mean_distance(a, b_scene, options.mean, a_known, a_first_bounds);
  result.b_to_a = directed_mean_distance(b, a_scene, options.mean, b_known, b_first_bounds);
  // The shared first pass counts once, with the Hausdorff search.
  result.hausdorff.a_to_b.queries += a_vertices.queries;
  result.hausdorff.b_to_a.queries += b_vertices.queries;
  result.shared = std::move(shared);
  return result;
}

}  // namespace holebench
