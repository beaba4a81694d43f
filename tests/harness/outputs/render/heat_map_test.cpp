#include "harness/outputs/render/heat_map.h"

#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench::render {
namespace {

bool same(const Rgb& a, const Rgb& b) {
  return a.r == b.r && a.g == b.g && a.b == b.b;
}

// 0 takes the first stop, the scale's maximum and beyond take the last, the middle the
// middle stop (five stops: the third).
TEST(HeatMap, ColoursFollowTheStops) {
  const HeatScale scale{0.02};
  const auto& stops = heat_stops();
  ASSERT_EQ(stops.size(), 5u);
  EXPECT_TRUE(same(heat_colour(0.0, scale), stops.front()));
  EXPECT_TRUE(same(heat_colour(0.02, scale), stops.back()));
  EXPECT_TRUE(same(heat_colour(1.0, scale), stops.back()));
  EXPECT_TRUE(same(heat_colour(0.01, scale), stops[2]));
}

// The scale is the case's (ground truth only): the same case gives the same scale, on
// 1-2-5 steps, whatever a method does. box/corner: the removed corner's radius over the
// diagonal, halved, rounded up.
TEST(HeatMap, CaseScaleIsANiceNumberFromTheCaseAlone) {
  const Case c = generators::make_case("box/corner");
  const HeatScale scale = case_heat_scale(c);
  EXPECT_EQ(scale.max_rel_diag, case_heat_scale(generators::make_case("box/corner")).max_rel_diag);
  const double mantissa =
      scale.max_rel_diag / std::pow(10.0, std::floor(std::log10(scale.max_rel_diag)));
  EXPECT_TRUE(std::abs(mantissa - 1.0) < 1e-9 || std::abs(mantissa - 2.0) < 1e-9 ||
              std::abs(mantissa - 5.0) < 1e-9)
      << scale.max_rel_diag;
  EXPECT_GT(scale.max_rel_diag, 0.0);
  EXPECT_LT(scale.max_rel_diag, 0.5);
}

TEST(HeatMap, LabelsAreShort) {
  EXPECT_EQ(heat_label(0.0), "0");
  EXPECT_EQ(heat_label(0.02), "0.02");
  EXPECT_EQ(heat_label(5e-05), "5e-05");
}

}  // namespace
}  // namespace holebench::render
