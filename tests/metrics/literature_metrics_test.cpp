// Invariant: each of the literature's metrics (metrics/literature_metrics.h) agrees with an
// independent computation within its stated error: a Monte Carlo estimate from uniformly
// random points (std::mt19937_64, faces drawn by area) and brute-force distances to every
// triangle, no Embree and no sampling scheme of ours. Six pairs, among them a flat patch
// across a crease, and analytic values where they exist.
#include "metrics/literature_metrics.h"

#include "core/distances.h"
#include "core/geometry.h"
#include "core/mesh_builder.h"
#include "generators/box_solid.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/shared_faces.h"
#include "metrics/surface_distance.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace holebench {
namespace {

// --- the independent reference ---------------------------------------------------------------

using Triangle = std::array<Point, 3>;

std::vector<Triangle> triangles_of(const Mesh& mesh) {
  std::vector<Triangle> triangles;
  for (auto f : mesh.faces()) {
    const auto c = face_corners(mesh, f);
    triangles.push_back({c[0], c[1], c[2]});
  }
  return triangles;
}

double area_of(const Triangle& t) {
  return 0.5 * OpenMesh::cross(t[1] - t[0], t[2] - t[0]).norm();
}

Point unit_normal(const Triangle& t) {
  const Point n = OpenMesh::cross(t[1] - t[0], t[2] - t[0]);
  return n / n.norm();
}

struct RandomPoint {
  Point point;
  Point normal;
};

// `count` points uniform over the surface's area.
std::vector<RandomPoint> uniform_points(const std::vector<Triangle>& triangles, std::size_t count,
                                        std::uint64_t seed) {
  std::vector<double> areas;
  for (const auto& t : triangles)
    areas.push_back(area_of(t));
  std::mt19937_64 random(seed);
  std::discrete_distribution<std::size_t> face(areas.begin(), areas.end());
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<RandomPoint> points;
  for (std::size_t i = 0; i < count; ++i) {
    const Triangle& t = triangles[face(random)];
    const double r1 = std::sqrt(unit(random)), r2 = unit(random);
    points.push_back(
        {t[0] * (1.0 - r1) + t[1] * (r1 * (1.0 - r2)) + t[2] * (r1 * r2), unit_normal(t)});
  }
  return points;
}

// Per point of A: the distance to B and the largest |cosine| with the normals of B's faces
// within `tolerance` of that distance, by brute force over every triangle of B.
struct BruteForce {
  std::vector<double> distances;
  std::vector<double> abs_cosines;
};

BruteForce brute_force(const std::vector<RandomPoint>& points, const std::vector<Triangle>& b,
                       double tolerance) {
  BruteForce out;
  std::vector<double> d(b.size());
  for (const auto& p : points) {
    for (std::size_t i = 0; i < b.size(); ++i)
      d[i] = (closest_point_on_triangle(p.point, b[i][0], b[i][1], b[i][2]) - p.point).norm();
    const double nearest = *std::min_element(d.begin(), d.end());
    double cosine = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      if (d[i] <= nearest + tolerance)
        cosine = std::max(cosine, std::abs(OpenMesh::dot(p.normal, unit_normal(b[i]))));
    }
    out.distances.push_back(nearest);
    out.abs_cosines.push_back(cosine);
  }
  return out;
}

struct Estimate {
  double value = 0.0;
  double error = 0.0;  ///< 4 standard errors
};

Estimate mean_of(const std::vector<double>& values) {
  double sum = 0.0, squares = 0.0;
  for (double v : values) {
    sum += v;
    squares += v * v;
  }
  const double n = static_cast<double>(values.size());
  const double mean = sum / n;
  const double variance = std::max(0.0, squares / n - mean * mean);
  return {mean, 4.0 * std::sqrt(variance / n)};
}

Estimate share_within(const std::vector<double>& distances, double tau) {
  std::vector<double> hits;
  for (double d : distances)
    hits.push_back(d <= tau ? 1.0 : 0.0);
  return mean_of(hits);
}

std::vector<double> squares_of(std::vector<double> values) {
  for (double& v : values)
    v *= v;
  return values;
}

// --- the pairs -------------------------------------------------------------------------------

struct Pair {
  std::string name;
  Mesh a, b;
  double tau;  ///< a threshold at which the shares are not all 0 or 1
};

Mesh grid(int n, double lift = 0.0) {
  TriangleSoup soup = test::grid_soup(n);
  for (auto& p : soup.points)
    p[2] += lift;
  return build_mesh(soup);
}

// A tent: two planes meeting at a ridge x = 0 of height h over [-1, 1] x [0, 1], each side a
// 4 x 2 grid of triangles; `plateau` > 0 cuts the ridge flat at that height (a flat patch
// across the crease).
Mesh tent(double h, double plateau = 0.0, double shift = 0.0) {
  TriangleSoup soup;
  const int nx = 8, ny = 2;
  for (int j = 0; j <= ny; ++j) {
    for (int i = 0; i <= nx; ++i) {
      const double x = -1.0 + 2.0 * i / nx;
      double z = h * (1.0 - std::abs(x));
      if (plateau > 0.0)
        z = std::min(z, plateau);
      soup.points.emplace_back(x + shift, static_cast<double>(j) / ny, z);
    }
  }
  const auto index = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return build_mesh(soup);
}

Mesh dented_box() {
  Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  for (auto v : box.vertices()) {
    const Point p = box.point(v);
    if (std::abs(p[0] - 1.0) < 1e-9 && std::abs(p[1] - 0.75) < 1e-9 && p[2] > 0.99)
      box.set_point(v, p + Point(0.0, 0.0, 0.2));
  }
  return box;
}

std::vector<Pair> pairs() {
  std::vector<Pair> out;
  out.push_back({"grid_and_lifted_grid", grid(3), grid(3, 0.3), 0.35});
  out.push_back({"grid_and_part", grid(3),
                 build_mesh(test::grid_without_cells(3, {{2, 0}, {2, 1}, {2, 2}})), 0.5});
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  out.push_back({"box_and_displaced_box", box, test::displaced(box, 0.05), 0.04});
  out.push_back({"box_and_dented_box", box, dented_box(), 0.05});
  // The repair crosses the crease: a plateau cut through the ridge, and a plane above it
  // (where the ridge itself is the nearest point and both sides are in the normal cone).
  out.push_back({"tent_and_plateau_across_the_crease", tent(0.5), tent(0.5, 0.3), 0.1});
  out.push_back({"tent_and_plane_above_the_crease", tent(0.5), grid(2, 0.6), 0.4});
  out.push_back({"tetrahedron_and_octahedron", build_mesh(test::tetrahedron_soup()),
                 build_mesh(test::octahedron_with_regions()), 0.1});
  return out;
}

constexpr std::size_t kMonteCarloPoints = 20'000;

TEST(LiteratureMetrics, ChamferDistanceMatchesMonteCarloWithinItsInterval) {
  for (const auto& pair : pairs()) {
    SCOPED_TRACE(pair.name);
    const embree::TriangleScene a_scene(pair.a), b_scene(pair.b);
    const auto d = surface_distance(pair.a, a_scene, pair.b, b_scene);
    ASSERT_TRUE(d.converged());
    const ChamferDistance c = chamfer_distance(distance_summary(d.hausdorff.a_to_b, d.a_to_b),
                                               distance_summary(d.hausdorff.b_to_a, d.b_to_a));
    const auto ta = triangles_of(pair.a), tb = triangles_of(pair.b);
    const auto a_to_b = brute_force(uniform_points(ta, kMonteCarloPoints, 1), tb, 0.0);
    const auto b_to_a = brute_force(uniform_points(tb, kMonteCarloPoints, 2), ta, 0.0);
    const Estimate m1 = mean_of(a_to_b.distances), m2 = mean_of(b_to_a.distances);
    // (+ 1e-12: round-off where every distance is the same and the estimate has no spread)
    const double l1 = 0.5 * (m1.value + m2.value), l1_error = 0.5 * (m1.error + m2.error) + 1e-12;
    EXPECT_LE(c.l1.lower, c.l1.value);
    EXPECT_LE(c.l1.value, c.l1.upper);
    EXPECT_GE(l1, c.l1.lower - l1_error);
    EXPECT_LE(l1, c.l1.upper + l1_error);
    const Estimate s1 = mean_of(squares_of(a_to_b.distances));
    const Estimate s2 = mean_of(squares_of(b_to_a.distances));
    const double l2 = 0.5 * (s1.value + s2.value), l2_error = 0.5 * (s1.error + s2.error) + 1e-12;
    EXPECT_GE(l2, c.l2.lower - l2_error);
    EXPECT_LE(l2, c.l2.upper + l2_error);
  }
}

TEST(LiteratureMetrics, AnalyticChamferDistances) {
  const auto chamfer = [](const Mesh& a, const Mesh& b) {
    const embree::TriangleScene a_scene(a), b_scene(b);
    SurfaceDistanceOptions options;
    options.mean.error_bound = 1e-5;
    options.mean.relative_error_bound = 0.0;
    const auto d = surface_distance(a, a_scene, b, b_scene, options);
    return chamfer_distance(distance_summary(d.hausdorff.a_to_b, d.a_to_b),
                            distance_summary(d.hausdorff.b_to_a, d.b_to_a));
  };
  // 0.3 apart everywhere: L1 = 0.3, L2 = 0.09.
  const auto lifted = chamfer(grid(3), grid(3, 0.3));
  EXPECT_NEAR(lifted.l1.value, 0.3, 1e-5);
  EXPECT_NEAR(lifted.l2.value, 0.09, 1e-5);
  // The grid against its part x <= 2: mean 1/6 and mean square 1/9 one way, 0 the other.
  const auto part =
      chamfer(grid(3), build_mesh(test::grid_without_cells(3, {{2, 0}, {2, 1}, {2, 2}})));
  EXPECT_NEAR(part.l1.value, 1.0 / 12.0, 1e-5);
  EXPECT_NEAR(part.l2.value, 1.0 / 18.0, 1e-5);
  EXPECT_LE(part.l1.lower, 1.0 / 12.0);
  EXPECT_GE(part.l1.upper, 1.0 / 12.0);
}

TEST(LiteratureMetrics, FScoreAndNormalConsistencyMatchMonteCarloWithinTheSamplingError) {
  for (const auto& pair : pairs()) {
    SCOPED_TRACE(pair.name);
    const embree::TriangleScene a_scene(pair.a), b_scene(pair.b);
    SampledAgreementOptions options;
    options.thresholds = {pair.tau};
    options.normal_cone.tolerance = 1e-3;
    const SharedFaces shared = shared_faces(pair.a, pair.b);
    const auto precision = sampled_agreement(pair.a, b_scene, options, &shared.b_face_of_a);
    const auto recall = sampled_agreement(pair.b, a_scene, options, &shared.a_face_of_b);
    const auto ta = triangles_of(pair.a), tb = triangles_of(pair.b);
    const auto a_to_b = brute_force(uniform_points(ta, kMonteCarloPoints, 3), tb, 1e-3);
    const auto b_to_a = brute_force(uniform_points(tb, kMonteCarloPoints, 4), ta, 1e-3);
    const Estimate p = share_within(a_to_b.distances, pair.tau);
    const Estimate r = share_within(b_to_a.distances, pair.tau);
    EXPECT_NEAR(precision.within_fraction[0], p.value, precision.fraction_error + p.error);
    EXPECT_NEAR(recall.within_fraction[0], r.value, recall.fraction_error + r.error);
    // F = 2PR / (P + R) moves by at most the largest of the two errors times 2.
    const double f_error =
        2.0 * std::max(precision.fraction_error + p.error, recall.fraction_error + r.error);
    EXPECT_NEAR(f_score(precision.within_fraction[0], recall.within_fraction[0]),
                f_score(p.value, r.value), f_error);
    // Normal consistency: |cosine| in [0, 1] has the same worst-case sampling error.
    const Estimate ca = mean_of(a_to_b.abs_cosines), cb = mean_of(b_to_a.abs_cosines);
    EXPECT_NEAR(0.5 * (precision.abs_cosine_mean + recall.abs_cosine_mean),
                0.5 * (ca.value + cb.value),
                0.5 * (precision.fraction_error + recall.fraction_error + ca.error + cb.error));
  }
}

// A's faces in two parts sampled apart (as the whole model's metrics sample a repair's input
// faces and its new faces under noise), each with the full count, combined by area: the same
// Monte Carlo reference over the whole of A, within the combined sampling error.
TEST(LiteratureMetrics, TwoPartsSampledApartMatchMonteCarloWithinTheSamplingError) {
  for (const auto& pair : pairs()) {
    SCOPED_TRACE(pair.name);
    const embree::TriangleScene b_scene(pair.b);
    SampledAgreementOptions options;
    options.thresholds = {pair.tau};
    options.normal_cone.tolerance = 1e-3;
    const SharedFaces shared = shared_faces(pair.a, pair.b);
    const std::vector<double> areas = face_areas(pair.a);
    const std::size_t middle = areas.size() / 2;
    SampledFaces first_part, second_part;
    tally_faces({areas.begin(), areas.begin() + middle}, &shared.b_face_of_a, 0, first_part);
    tally_faces({areas.begin() + middle, areas.end()}, &shared.b_face_of_a, middle, second_part);
    const auto first = sampled_agreement(pair.a, b_scene, options, &shared.b_face_of_a, nullptr,
                                         nullptr, &first_part);
    const auto second = sampled_agreement(pair.a, b_scene, options, &shared.b_face_of_a, nullptr,
                                          nullptr, &second_part);
    const auto both = combined_agreement(first, second);
    EXPECT_EQ(both.samples, first.samples + second.samples);
    double area = 0.0;
    for (double face : areas)
      area += face;
    EXPECT_NEAR(both.area, area, 1e-12 * area);
    const auto a_to_b = brute_force(uniform_points(triangles_of(pair.a), kMonteCarloPoints, 5),
                                    triangles_of(pair.b), 1e-3);
    const Estimate p = share_within(a_to_b.distances, pair.tau);
    EXPECT_NEAR(both.within_fraction[0], p.value, both.fraction_error + p.error);
    const Estimate c = mean_of(a_to_b.abs_cosines);
    EXPECT_NEAR(both.abs_cosine_mean, c.value, both.fraction_error + c.error);
  }
}

// Two parts of unequal area, one wholly within tau of B and one wholly beyond it: the share
// within is the first part's share of the area, exactly (each part's samples all agree).
TEST(LiteratureMetrics, TwoPartsWeighByTheirAreas) {
  TriangleSoup soup;  // a unit square 1e-3 above B and a 3 x 3 square 1 above it
  soup.points = {Point(0, 0, 1e-3), Point(1, 0, 1e-3), Point(1, 1, 1e-3), Point(0, 1, 1e-3),
                 Point(0, 0, 1),    Point(3, 0, 1),    Point(3, 3, 1),    Point(0, 3, 1)};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}, {4, 6, 7}};
  const Mesh a = build_mesh(soup);
  const Mesh b = build_mesh(test::grid_soup(4));
  const embree::TriangleScene b_scene(b);
  SampledAgreementOptions options;
  options.thresholds = {0.01};
  options.samples = 1000;
  const std::vector<double> areas = face_areas(a);
  SampledFaces near_part, far_part;
  tally_faces({areas.begin(), areas.begin() + 2}, nullptr, 0, near_part);
  tally_faces({areas.begin() + 2, areas.end()}, nullptr, 2, far_part);
  const auto near = sampled_agreement(a, b_scene, options, nullptr, nullptr, nullptr, &near_part);
  const auto far = sampled_agreement(a, b_scene, options, nullptr, nullptr, nullptr, &far_part);
  ASSERT_EQ(near.within_fraction[0], 1.0);
  ASSERT_EQ(far.within_fraction[0], 0.0);
  EXPECT_DOUBLE_EQ(combined_agreement(near, far).within_fraction[0], 0.1);
  EXPECT_DOUBLE_EQ(combined_agreement(far, near).within_fraction[0], 0.1);
  EXPECT_NEAR(combined_agreement(near, far).abs_cosine_mean, 1.0, 1e-12);  // parallel planes
}

TEST(LiteratureMetrics, APartWithoutAreaLeavesTheOtherAsItIs) {
  SampledAgreement part;
  part.within_fraction = {0.25, 0.5};
  part.abs_cosine_mean = 0.75;
  part.area = 2.0;
  part.sampled_area = 1.5;
  part.samples = 100;
  part.fraction_error = 0.1;
  SampledAgreement none;
  none.within_fraction = {0.0, 0.0};
  for (const auto& both : {combined_agreement(part, none), combined_agreement(none, part)}) {
    EXPECT_EQ(both.within_fraction, part.within_fraction);
    EXPECT_EQ(both.abs_cosine_mean, part.abs_cosine_mean);
    EXPECT_EQ(both.samples, part.samples);
    EXPECT_EQ(both.fraction_error, part.fraction_error);
  }
  // Two parts of equal area: the mean of their fractions, the error sqrt(2) / 2 of each.
  SampledAgreement other = part;
  other.within_fraction = {0.75, 1.0};
  other.abs_cosine_mean = 0.25;
  const auto both = combined_agreement(part, other);
  EXPECT_DOUBLE_EQ(both.within_fraction[0], 0.5);
  EXPECT_DOUBLE_EQ(both.within_fraction[1], 0.75);
  EXPECT_DOUBLE_EQ(both.abs_cosine_mean, 0.5);
  EXPECT_DOUBLE_EQ(both.area, 4.0);
  EXPECT_DOUBLE_EQ(both.fraction_error, 0.1 * std::sqrt(0.5));
}

// The sampled shares are neither all 0 nor all 1 on most pairs: the comparison above tests
// something.
TEST(LiteratureMetrics, ThePairsHaveFractionalShares) {
  int fractional = 0;
  for (const auto& pair : pairs()) {
    const embree::TriangleScene b_scene(pair.b);
    SampledAgreementOptions options;
    options.thresholds = {pair.tau};
    const double p = sampled_agreement(pair.a, b_scene, options).within_fraction[0];
    fractional += p > 0.02 && p < 0.98 ? 1 : 0;
  }
  EXPECT_GE(fractional, 4);
}

TEST(LiteratureMetrics, SharedFacesCountExactlyAndIdenticalMeshesAgreeFully) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const embree::TriangleScene scene(box);
  const SharedFaces shared = shared_faces(box, box);
  SampledAgreementOptions options;
  options.thresholds = {1e-6};
  const auto a = sampled_agreement(box, scene, options, &shared.b_face_of_a);
  EXPECT_EQ(a.samples, 0u);  // nothing left to sample
  EXPECT_EQ(a.within_fraction[0], 1.0);
  EXPECT_EQ(a.abs_cosine_mean, 1.0);
  EXPECT_EQ(a.fraction_error, 0.0);
  // Without the shared faces the samples find the same.
  const auto sampled = sampled_agreement(box, scene, options);
  EXPECT_EQ(sampled.samples, options.samples);
  EXPECT_DOUBLE_EQ(sampled.within_fraction[0], 1.0);
  EXPECT_NEAR(sampled.abs_cosine_mean, 1.0, 1e-12);
}

TEST(LiteratureMetrics, SamplingIsDeterministic) {
  const Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  const Mesh moved = test::displaced(box, 0.05);
  const embree::TriangleScene scene(moved);
  SampledAgreementOptions options;
  options.thresholds = {0.02, 0.04};
  const auto first = sampled_agreement(box, scene, options);
  const auto second = sampled_agreement(box, scene, options);
  EXPECT_EQ(first.within_fraction, second.within_fraction);
  EXPECT_EQ(first.abs_cosine_mean, second.abs_cosine_mean);
}

TEST(LiteratureMetrics, FScoreOfPrecisionAndRecall) {
  EXPECT_EQ(f_score(0.0, 0.0), 0.0);
  EXPECT_EQ(f_score(1.0, 1.0), 1.0);
  EXPECT_DOUBLE_EQ(f_score(1.0, 0.5), 2.0 / 3.0);
}

// Edge Chamfer distance: the truth's ridge at x = 0, the repair's at x = d, both the full
// length: every point of either is d from the other.
TEST(EdgeChamferDistance, AParallelRidgeIsItsOffsetAway) {
  const Mesh complete = tent(0.5);
  std::vector<int> removed;
  for (auto f : complete.faces())
    removed.push_back(f.idx());
  for (double d : {0.0, 0.05, 0.125}) {
    Mesh repaired = tent(0.5, 0.0, d);
    for (auto f : repaired.faces())
      repaired.data(f).provenance = Provenance::New;
    const auto e = edge_chamfer_distance(complete, removed, repaired);
    ASSERT_TRUE(e.has_value());
    EXPECT_NEAR(*e, d, 1e-12);
  }
  // A flat repair has no sharp edge: the distance is not defined.
  Mesh flat = grid(2);
  for (auto f : flat.faces())
    flat.data(f).provenance = Provenance::New;
  EXPECT_FALSE(edge_chamfer_distance(complete, removed, flat).has_value());
  // Nor where the faces around the truth's ridge were not removed.
  Mesh shifted = tent(0.5, 0.0, 0.05);
  for (auto f : shifted.faces())
    shifted.data(f).provenance = Provenance::New;
  EXPECT_FALSE(edge_chamfer_distance(complete, {}, shifted).has_value());
}

// A plateau across the crease: the tent of height 2 (slopes 2, a ridge of 127 degrees) cut
// at 1.5 has two creases at x = +-0.25, z = 1.5 (63 degrees) instead of the ridge at x = 0,
// z = 2. Every point of either is sqrt(0.25^2 + 0.5^2) from the other (parallel lines of the
// same length).
TEST(EdgeChamferDistance, APlateauAcrossTheCrease) {
  const Mesh complete = tent(2.0);
  std::vector<int> removed;
  for (auto f : complete.faces())
    removed.push_back(f.idx());
  Mesh repaired = tent(2.0, 1.5);
  for (auto f : repaired.faces())
    repaired.data(f).provenance = Provenance::New;
  const auto e = edge_chamfer_distance(complete, removed, repaired);
  ASSERT_TRUE(e.has_value());
  EXPECT_NEAR(*e, std::sqrt(0.25 * 0.25 + 0.5 * 0.5), 1e-12);
  // A gentler plateau (the tent of height 0.5 cut at 0.3) bends by less than 30 degrees at
  // each grid line: no sharp edge in the repair, no distance.
  Mesh gentle = tent(0.5, 0.3);
  for (auto f : gentle.faces())
    gentle.data(f).provenance = Provenance::New;
  EXPECT_FALSE(edge_chamfer_distance(tent(0.5), removed, gentle).has_value());
}

}  // namespace
}  // namespace holebench

namespace holebench {
namespace {

// A tally continued from any face on equals the tally over every face, sum for sum (the same
// order); an agreement given it equals the one that tallies A itself, bit for bit.
TEST(LiteratureMetrics, ATallyContinuedEqualsTheWholeTally) {
  for (const auto& pair : pairs()) {
    SCOPED_TRACE(pair.name);
    const SharedFaces shared = shared_faces(pair.a, pair.b);
    const std::vector<double> areas = face_areas(pair.a);
    const SampledFaces whole = sampled_faces(areas, &shared.b_face_of_a);
    for (std::size_t first : {std::size_t{0}, areas.size() / 3, areas.size()}) {
      SampledFaces tally = sampled_faces(std::vector<double>(areas.begin(), areas.begin() + first),
                                         &shared.b_face_of_a);
      tally_faces(std::vector<double>(areas.begin() + first, areas.end()), &shared.b_face_of_a,
                  first, tally);
      EXPECT_EQ(tally.area, whole.area);
      EXPECT_EQ(tally.shared_area, whole.shared_area);
      EXPECT_EQ(tally.unshared_area, whole.unshared_area);
      EXPECT_EQ(tally.faces, whole.faces);
      EXPECT_EQ(tally.cumulative, whole.cumulative);
      // The same continued from the tally before `first` without copying it
      // (continued_tally): the same faces, sums and samples.
      const SampledFaces before = sampled_faces(
          std::vector<double>(areas.begin(), areas.begin() + first), &shared.b_face_of_a);
      SampledFaces continued = continued_tally(before);
      tally_faces(std::vector<double>(areas.begin() + first, areas.end()), &shared.b_face_of_a,
                  first, continued);
      EXPECT_EQ(continued.area, whole.area);
      EXPECT_EQ(continued.shared_area, whole.shared_area);
      EXPECT_EQ(continued.unshared_area, whole.unshared_area);
      ASSERT_EQ(continued.size(), whole.faces.size());
      for (std::size_t i = 0; i < whole.faces.size(); ++i) {
        ASSERT_EQ(continued.face(i), whole.faces[i]) << i;
        ASSERT_EQ(continued.running_sum(i), whole.cumulative[i]) << i;
      }
      const AreaSamples from_whole = tally_samples(pair.a, 500, whole);
      const AreaSamples from_continued = tally_samples(pair.a, 500, continued);
      EXPECT_EQ(from_continued.points, from_whole.points);
      EXPECT_EQ(from_continued.faces, from_whole.faces);
    }
    const embree::TriangleScene b_scene(pair.b);
    SampledAgreementOptions options;
    options.thresholds = {pair.tau};
    const auto alone = sampled_agreement(pair.a, b_scene, options, &shared.b_face_of_a);
    const auto given =
        sampled_agreement(pair.a, b_scene, options, &shared.b_face_of_a, nullptr, nullptr, &whole);
    EXPECT_EQ(alone.within_fraction, given.within_fraction);
    EXPECT_EQ(alone.abs_cosine_mean, given.abs_cosine_mean);
    EXPECT_EQ(alone.area, given.area);
    EXPECT_EQ(alone.sampled_area, given.sampled_area);
  }
}

// Each sample lies on the face a walk along the running sums finds (the first face from the
// previous sample's on whose sum reaches the sample's share of the total, or the last face):
// runs of equal sums, a few faces holding most of the area, more samples than faces and fewer,
// and shares that fall exactly on a sum.
TEST(LiteratureMetrics, ASampleLiesOnTheFaceAWalkAlongTheSumsFinds) {
  const Mesh mesh = build_mesh(test::grid_soup(40));  // 3200 faces: any index below
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    SCOPED_TRACE(trial);
    // Trials 0 and 1: 2048 unit areas (every other one 1e-30 in trial 1, which leaves the sum
    // as it was) and 1024 or 512 samples: every share (k + 1/2) / count of the total is then
    // exactly an integer, a running sum. The others: random.
    const bool exact = trial < 2;
    const std::size_t faces = exact ? 2048 * (1 + trial) : 1 + random() % 3000;
    SampledFaces tally;
    double sum = 0.0;
    for (std::size_t i = 0; i < faces; ++i) {
      const double draw = unit(random);
      // Mostly tiny areas (sums that stay equal in double precision: 1e-30 of 1), some large.
      const double area = exact         ? (trial == 1 && i % 2 == 1 ? 1e-30 : 1.0)
                          : draw < 0.5  ? 1e-30
                          : draw < 0.95 ? draw
                                        : 1e3 * draw;
      sum += area;
      tally.faces.push_back(static_cast<int>(i));
      tally.cumulative.push_back(sum);
    }
    tally.area = tally.unshared_area = sum;
    const std::size_t count = exact ? 1024 / (1 + trial) : 1 + random() % 5000;
    const AreaSamples samples = tally_samples(mesh, count, tally);
    ASSERT_EQ(samples.faces.size(), count);
    std::size_t face = 0, exact_hits = 0;
    for (std::size_t k = 0; k < count; ++k) {
      const double at = (static_cast<double>(k) + 0.5) / static_cast<double>(count) * sum;
      while (face + 1 < faces && tally.cumulative[face] < at)
        ++face;
      exact_hits += tally.cumulative[face] == at ? 1 : 0;
      ASSERT_EQ(samples.faces[k], static_cast<int>(face)) << k;
    }
    if (exact) {
      EXPECT_EQ(exact_hits, count);  // the construction does what it says
    }
  }
}

}  // namespace
}  // namespace holebench
