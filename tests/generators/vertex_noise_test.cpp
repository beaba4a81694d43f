#include "generators/vertex_noise.h"

#include "generators/box_solid.h"
#include "generators/case_catalog.h"
#include "generators/random.h"

#include <gtest/gtest.h>

#include <cstring>

namespace holebench::generators {
namespace {

TEST(Random, KnownSplitMix64Sequence) {
  // Reference values of SplitMix64 for seed 1234567 (Vigna's splitmix64.c).
  Random random(1234567);
  EXPECT_EQ(random.next(), 6457827717110365317ull);
  EXPECT_EQ(random.next(), 3203168211198807973ull);
  EXPECT_EQ(random.next(), 9817491932198370423ull);
}

TEST(Random, UniformIsInRangeAndUnitVectorsAreUnit) {
  Random random(7);
  for (int i = 0; i < 1000; ++i) {
    const double u = random.uniform();
    EXPECT_GE(u, 0.0);
    EXPECT_LT(u, 1.0);
    EXPECT_NEAR(random.unit_vector().norm(), 1.0, 1e-15);
  }
}

TEST(VertexNoise, EveryVertexMovesByExactlyTheLevel) {
  const Mesh clean = make_box({Point(2.0, 1.5, 1.0), 0.25});
  Mesh noisy = clean;
  NoiseOptions options;
  options.percent = 25.0;
  options.reference_length = noise_reference_length(clean);
  options.seed = 99;
  add_vertex_noise(noisy, options);
  const double expected = 0.25 * 0.01 * std::sqrt(4.0 + 2.25 + 1.0);
  for (auto v : clean.vertices()) {
    EXPECT_NEAR((noisy.point(v) - clean.point(v)).norm(), expected, 1e-12);
  }
}

TEST(VertexNoise, ZeroPercentChangesNothing) {
  const Mesh clean = make_box({Point(1.0, 1.0, 1.0), 0.25});
  Mesh same = clean;
  add_vertex_noise(same, {0.0, 1.0, 5});
  for (auto v : clean.vertices())
    EXPECT_EQ(same.point(v), clean.point(v));
}

// Determinism: same id, seed and level give the same input bit for bit; another seed
// another one; the ground truth stays clean.
TEST(VertexNoise, CatalogNoiseIsDeterministicAndLeavesTheGroundTruthClean) {
  const Case a = make_case("box/edge", 3, 5.0);
  const Case b = make_case("box/edge", 3, 5.0);
  const Case c = make_case("box/edge", 4, 5.0);
  const Case clean = make_case("box/edge", 3, 0.0);
  ASSERT_EQ(a.input.n_vertices(), b.input.n_vertices());
  bool differs_from_other_seed = false;
  for (auto v : a.input.vertices()) {
    const Point& p = a.input.point(v);
    const Point& q = b.input.point(b.input.vertex_handle(v.idx()));
    EXPECT_EQ(std::memcmp(&p, &q, sizeof(Point)), 0);
    differs_from_other_seed |= p != c.input.point(c.input.vertex_handle(v.idx()));
  }
  EXPECT_TRUE(differs_from_other_seed);
  for (auto v : a.complete.vertices()) {
    EXPECT_EQ(a.complete.point(v), clean.complete.point(clean.complete.vertex_handle(v.idx())));
  }
  EXPECT_EQ(a.noise_percent, 5.0);
  EXPECT_EQ(a.seed, 3u);
}

}  // namespace
}  // namespace holebench::generators
