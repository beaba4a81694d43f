#include "metrics/literature_metrics.h"

#include "core/geometry.h"
#include "core/nearest_segment.h"
#include "core/portable_math.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/face_subset.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace holebench {

namespace {

// The R2 sequence (Roberts' generalised golden ratio): a fixed low-discrepancy point in the
// unit square for each index, the same on every machine.
std::pair<double, double> r2_point(std::size_t i) {
  constexpr double g = 1.32471795724474602596;  // the plastic number
  constexpr double a1 = 1.0 / g, a2 = 1.0 / (g * g);
  const double n = static_cast<double>(i + 1);
  return {std::fmod(0.5 + a1 * n, 1.0), std::fmod(0.5 + a2 * n, 1.0)};
}

// A point of triangle (a, b, c) from a point (u, v) of the unit square, uniform by area.
Point in_triangle(const Point& a, const Point& b, const Point& c, double u, double v) {
  if (u + v > 1.0) {
    u = 1.0 - u;
    v = 1.0 - v;
  }
  return a + (b - a) * u + (c - a) * v;
}

// The sharp edges (|dihedral| >= the threshold) of `mesh` that bound a face of `faces`, in
// edge index order (the order of a pass over every edge): found from those faces' own edges,
// at the cost of the region. Boundary edges have no dihedral angle and are not sharp.
std::vector<SegmentEnds> sharp_edges_around(const Mesh& mesh, double sharp_angle_degrees,
                                            const std::vector<int>& faces) {
  const double threshold = sharp_angle_degrees * kPi / 180.0;
  std::vector<int> edge_indices;
  for (int f : faces) {
    for (auto h : mesh.fh_range(FaceHandle(f)))
      edge_indices.push_back(mesh.edge_handle(h).idx());
  }
  std::sort(edge_indices.begin(), edge_indices.end());
  edge_indices.erase(std::unique(edge_indices.begin(), edge_indices.end()), edge_indices.end());
  std::vector<SegmentEnds> edges;
  for (int index : edge_indices) {
    const EdgeHandle e(index);
    if (mesh.status(e).deleted() || mesh.is_boundary(e))
      continue;
    if (std::abs(signed_dihedral_angle(mesh, e)) >= threshold)
      edges.push_back({mesh.point(mesh.from_vertex_handle(mesh.halfedge_handle(e, 0))),
                       mesh.point(mesh.to_vertex_handle(mesh.halfedge_handle(e, 0)))});
  }
  return edges;
}

// A point on a polyline standing for `length` of it (the midpoint rule).
struct EdgeSample {
  Point point;
  double length = 0.0;
};

std::vector<EdgeSample> sample_segments(const std::vector<SegmentEnds>& segments, double spacing) {
  std::vector<EdgeSample> samples;
  for (const auto& s : segments) {
    const double length = (s.b - s.a).norm();
    const int steps = std::max(1, static_cast<int>(std::ceil(length / spacing)));
    for (int i = 0; i < steps; ++i)
      samples.push_back({s.a + (s.b - s.a) * ((i + 0.5) / steps), length / steps});
  }
  return samples;
}

// The length-weighted mean distance of the samples to the nearest segment.
double mean_distance_to_segments(const std::vector<EdgeSample>& samples,
                                 const std::vector<SegmentEnds>& segments) {
  const NearestSegment nearest(segments);
  double sum = 0.0, length = 0.0;
  for (const auto& sample : samples) {
    const double best = nearest.distance(sample.point);
    sum += best * sample.length;
    length += sample.length;
  }
  return length > 0.0 ? sum / length : 0.0;
}

}  // namespace

ChamferDistance chamfer_distance(const DistanceSummary& a_to_b, const DistanceSummary& b_to_a) {
  ChamferDistance c;
  c.l1 = {0.5 * (a_to_b.mean.lower + b_to_a.mean.lower),
          0.5 * (a_to_b.mean.value + b_to_a.mean.value),
          0.5 * (a_to_b.mean.upper + b_to_a.mean.upper)};
  const auto square = [](double x) { return x * x; };
  c.l2 = {0.5 * (square(a_to_b.rms.lower) + square(b_to_a.rms.lower)),
          0.5 * (square(a_to_b.rms.value) + square(b_to_a.rms.value)),
          0.5 * (square(a_to_b.rms.upper) + square(b_to_a.rms.upper))};
  return c;
}

void tally_faces(const std::vector<double>& face_areas, const std::vector<int>* b_face_of_a,
                 std::size_t first, SampledFaces& tally) {
  // By index (a deleted face has no area): the faces in order, without the mesh's iterator.
  for (std::size_t i = 0; i < face_areas.size(); ++i) {
    const std::size_t f = first + i;
    const double area = face_areas[i];
    if (!(area > 0.0))
      continue;
    tally.area += area;
    if (b_face_of_a && (*b_face_of_a)[f] >= 0) {
      tally.shared_area += area;
      continue;
    }
    tally.unshared_area += area;
    tally.faces.push_back(static_cast<int>(f));
    tally.cumulative.push_back(tally.unshared_area);
  }
}

SampledFaces sampled_faces(const std::vector<double>& face_areas,
                           const std::vector<int>* b_face_of_a) {
  SampledFaces tally;
  tally_faces(face_areas, b_face_of_a, 0, tally);
  return tally;
}

int SampledFaces::face(std::size_t i) const {
  const std::size_t earlier = before ? before->size() : 0;
  return i < earlier ? before->face(i) : faces[i - earlier];
}

double SampledFaces::running_sum(std::size_t i) const {
  const std::size_t earlier = before ? before->size() : 0;
  return i < earlier ? before->running_sum(i) : cumulative[i - earlier];
}

SampledFaces continued_tally(const SampledFaces& before) {
  SampledFaces tally;
  tally.area = before.area;
  tally.shared_area = before.shared_area;
  tally.unshared_area = before.unshared_area;
  tally.before = &before;
  return tally;
}

namespace {

// The first position from `from` on whose running sum reaches `at`, or the last position
// (`size` - 1) where none does: the step a walk from `from` would stop at, found by doubling
// the stride and then halving it (the sums do not decrease), so that a sample costs the
// logarithm of the faces it passes, not their number.
template <class Sum>
std::size_t first_reaching(const Sum& sum, std::size_t size, std::size_t from, double at) {
  const std::size_t last = size - 1;
  if (from >= last || !(sum(from) < at))
    return from;
  // sum(low) < at throughout; high is last or a position whose sum reaches at.
  std::size_t low = from, stride = 1;
  while (low + stride < last && sum(low + stride) < at) {
    low += stride;
    stride *= 2;
  }
  std::size_t high = std::min(low + stride, last);
  while (high - low > 1) {
    const std::size_t middle = low + (high - low) / 2;
    if (sum(middle) < at)
      low = middle;
    else
      high = middle;
  }
  return high;
}

// `count` points spread by area over the tally's faces (with the running sum of their
// areas): systematic sampling, point k at cumulative area (k + 1/2) / count of the total.
AreaSamples samples_on(const Mesh& a, std::size_t count, const SampledFaces& tally) {
  AreaSamples samples;
  const std::size_t size = tally.size();
  if (size == 0 || count == 0)
    return samples;
  const auto sum = [&tally](std::size_t i) { return tally.running_sum(i); };
  const double total = sum(size - 1);
  samples.points.reserve(count);
  std::size_t position = 0;
  for (std::size_t k = 0; k < count; ++k) {
    const double at = (static_cast<double>(k) + 0.5) / static_cast<double>(count) * total;
    position = first_reaching(sum, size, position, at);
    const int face = tally.face(position);
    const auto corners = face_corners(a, a.face_handle(face));
    const auto [u, v] = r2_point(k);
    samples.points.push_back(in_triangle(corners[0], corners[1], corners[2], u, v));
    samples.faces.push_back(face);
    samples.normals.push_back(triangle_unit_normal(corners[0], corners[1], corners[2]));
  }
  return samples;
}

}  // namespace

AreaSamples area_samples(const Mesh& a, std::size_t count, const std::vector<bool>* skip) {
  const std::vector<double> areas = face_areas(a);
  SampledFaces tally;  // only the faces and their running sums: what samples_on() reads
  double total = 0.0;
  for (std::size_t f = 0; f < areas.size(); ++f) {
    if ((skip && (*skip)[f]) || !(areas[f] > 0.0))
      continue;
    total += areas[f];
    tally.faces.push_back(static_cast<int>(f));
    tally.cumulative.push_back(total);
  }
  return samples_on(a, count, tally);
}

AreaSamples tally_samples(const Mesh& a, std::size_t count, const SampledFaces& tally) {
  if (!(tally.area > 0.0) || !(tally.area - tally.shared_area > 0.0))
    return {};
  return samples_on(a, count, tally);
}

namespace {

// The normal cone's answer at each sample: `known`'s where it took the same points (and
// normals), else asked of the scene.
std::vector<NormalConeAngle> cone_answers(const AreaSamples& samples,
                                          const embree::TriangleScene& b_scene,
                                          const NormalConeOptions& options,
                                          const SampledAnswers* known) {
  if (known && known->points == samples.points && known->normals == samples.normals)
    return known->cones;
  std::vector<NormalConeAngle> cones;
  cones.reserve(samples.points.size());
  for (std::size_t i = 0; i < samples.points.size(); ++i)
    cones.push_back(normal_cone_angle(b_scene, samples.points[i], samples.normals[i], options));
  return cones;
}

}  // namespace

SampledAgreement sampled_agreement(const Mesh& a, const embree::TriangleScene& b_scene,
                                   const SampledAgreementOptions& options,
                                   const std::vector<int>* b_face_of_a, const SampledAnswers* known,
                                   SampledAnswers* answers, const SampledFaces* known_faces) {
  SampledAgreement agreement;
  if (answers)
    *answers = {};
  agreement.within_fraction.assign(options.thresholds.size(), 0.0);
  // A's faces tallied once, for the sums and the samples.
  SampledFaces computed;
  if (!known_faces)
    computed = sampled_faces(face_areas(a), b_face_of_a);
  const SampledFaces& tally = known_faces ? *known_faces : computed;
  agreement.area = tally.area;
  if (!(agreement.area > 0.0))
    return agreement;
  agreement.sampled_area = agreement.area - tally.shared_area;
  const double shared_share = tally.shared_area / agreement.area;
  const double sampled_share = 1.0 - shared_share;
  const AreaSamples samples = tally_samples(a, options.samples, tally);
  agreement.samples = samples.points.size();
  std::vector<std::size_t> within(options.thresholds.size(), 0);
  double cosine_sum = 0.0;
  std::vector<NormalConeAngle> cones = cone_answers(samples, b_scene, options.normal_cone, known);
  for (const NormalConeAngle& cone : cones) {
    cosine_sum += cone.largest_abs_cosine;
    for (std::size_t t = 0; t < options.thresholds.size(); ++t)
      within[t] += cone.nearest_distance <= options.thresholds[t] ? 1 : 0;
  }
  const double n = static_cast<double>(samples.points.size());
  for (std::size_t t = 0; t < options.thresholds.size(); ++t)
    agreement.within_fraction[t] = shared_share + (n > 0.0 ? sampled_share * within[t] / n : 0.0);
  agreement.abs_cosine_mean = shared_share + (n > 0.0 ? sampled_share * cosine_sum / n : 0.0);
  agreement.fraction_error = n > 0.0 ? sampled_share * 1.29 / std::sqrt(n) : 0.0;
  if (answers)
    *answers = {samples.points, samples.normals, std::move(cones)};
  return agreement;
}

SampledAgreement combined_agreement(const SampledAgreement& first, const SampledAgreement& second) {
  if (!(second.area > 0.0))
    return first;
  if (!(first.area > 0.0))
    return second;
  SampledAgreement both;
  both.area = first.area + second.area;
  both.sampled_area = first.sampled_area + second.sampled_area;
  both.samples = first.samples + second.samples;
  const double w1 = first.area / both.area, w2 = second.area / both.area;
  both.within_fraction.resize(first.within_fraction.size());
  for (std::size_t t = 0; t < both.within_fraction.size(); ++t)
    both.within_fraction[t] = w1 * first.within_fraction[t] + w2 * second.within_fraction[t];
  both.abs_cosine_mean = w1 * first.abs_cosine_mean + w2 * second.abs_cosine_mean;
  both.fraction_error = std::hypot(w1 * first.fraction_error, w2 * second.fraction_error);
  return both;
}

double f_score(double precision, double recall) {
  return precision + recall > 0.0 ? 2.0 * precision * recall / (precision + recall) : 0.0;
}

std::optional<double> edge_chamfer_distance(const Mesh& complete,
                                            const std::vector<int>& removed_faces,
                                            const Mesh& repaired, const EdgeChamferOptions& options,
                                            const std::vector<int>* repaired_new_faces) {
  const auto truth = sharp_edges_around(complete, options.sharp_angle_degrees, removed_faces);
  const auto repair =
      sharp_edges_around(repaired, options.sharp_angle_degrees,
                         repaired_new_faces ? *repaired_new_faces : new_face_indices(repaired));
  if (truth.empty() || repair.empty())
    return std::nullopt;
  const auto truth_points = sample_segments(truth, options.edge_sample_spacing);
  const auto repair_points = sample_segments(repair, options.edge_sample_spacing);
  return 0.5 * (mean_distance_to_segments(repair_points, truth) +
                mean_distance_to_segments(truth_points, repair));
}

}  // namespace holebench
