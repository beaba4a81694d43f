// The papers' methods run their papers' steps as written by default (issue 47): each
// departure the project keeps is an option, off by default, and the named variants turn
// them on. These tests read the defaults, not a run.
#include "methods/brep_guidance/brep_guidance.h"
#include "methods/crest_feature/crest_feature.h"
#include "methods/registry.h"
#include "methods/slice_loft/slice_loft.h"
#include "methods/slice_loft/slice_loft_variants.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

namespace holebench {
namespace {

TEST(PaperDefaults, SliceLoftRunsSection4AsWritten) {
  for (const char* id : {"slice_loft", "slice_direct"}) {
    const auto method = make_method(id);
    const auto* slice = dynamic_cast<const SliceLoftMethod*>(method.get());
    ASSERT_NE(slice, nullptr) << id;
    const SliceLoftOptions& o = slice->slice_options();
    // 4.1: the influencing area is the hole's box enlarged by 10 % of its diagonal, nothing more.
    EXPECT_DOUBLE_EQ(o.identification.influence_margin_rel_box, 0.1) << id;
    EXPECT_DOUBLE_EQ(o.identification.min_influence_margin_edges, 0.0) << id;
    // 4.4: sections from the hole's boundary to the other end of the slice on the boundary,
    // traced from one end, slices of the portion only, advancing along the box's longer edge.
    EXPECT_EQ(o.surface.extent, slice_loft::SectionExtent::HoleBoundary) << id;
    EXPECT_EQ(o.surface.tracing, slice_loft::GapTracing::OneEnd) << id;
    EXPECT_EQ(o.surface.extra_slices, 0) << id;
    EXPECT_EQ(o.surface.direction, slice_loft::SlicingDirection::LongerBoxEdge) << id;
    // 4.5: trimmed in the surface's own parameter domain first.
    EXPECT_FALSE(o.tessellation.plane_first) << id;
  }
  const auto direct = make_method("slice_direct");
  EXPECT_TRUE(
      dynamic_cast<const SliceLoftMethod*>(direct.get())->slice_options().tessellation.direct);
}

TEST(PaperDefaults, SliceLoftPlusTakesEveryDepartureAndTheAblationOneEach) {
  for (const char* id : {"slice_loft_plus", "slice_direct_plus"}) {
    const auto method = make_method(id);
    const auto& o = dynamic_cast<const SliceLoftMethod*>(method.get())->slice_options();
    EXPECT_EQ(o.surface.extent, slice_loft::SectionExtent::InfluencingArea) << id;
    EXPECT_EQ(o.surface.tracing, slice_loft::GapTracing::BothEnds) << id;
    EXPECT_EQ(o.surface.extra_slices, 2) << id;
    EXPECT_EQ(o.surface.direction, slice_loft::SlicingDirection::MajorAxis) << id;
    EXPECT_DOUBLE_EQ(o.identification.min_influence_margin_edges, 3.0) << id;
    EXPECT_TRUE(o.tessellation.plane_first) << id;
  }
  // Each ablation method's recorded options differ from its paper method's and from every
  // other ablation method's.
  const MethodOptions loft = make_method("slice_loft")->options();
  const MethodOptions direct = make_method("slice_direct")->options();
  const auto ablation = make_ablation_methods();
  EXPECT_EQ(ablation.size(), 2 * slice_loft::departures().size());
  for (std::size_t i = 0; i < ablation.size(); ++i) {
    const MethodOptions o = ablation[i]->options();
    EXPECT_NE(o, loft) << ablation[i]->id();
    EXPECT_NE(o, direct) << ablation[i]->id();
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_NE(o, ablation[j]->options()) << ablation[i]->id() << " " << ablation[j]->id();
  }
}

TEST(PaperDefaults, CrestFeatureTakesTheCrestPointsAndTheBoundaryCrossing) {
  const auto method = make_method("crest_feature");
  const auto& o = dynamic_cast<const CrestFeatureMethod*>(method.get())->crest_options();
  // 3.4.3: "the pair of feature points on the hole boundary and their adjacent crest points
  // make four initial control points".
  EXPECT_EQ(o.interpolation.control_points, crest_feature::ControlPoints::CrestPoints);
  // 3.4.1: the feature point is "the intersection point between the crest line ... with the
  // hole boundary", inserted into the boundary edge it crosses.
  EXPECT_TRUE(o.feature_points.on_boundary_edges);
  EXPECT_NE(make_method("crest_feature")->options(), make_method("crest_feature_plus")->options());
}

TEST(PaperDefaults, CrestFeaturePlusTakesTheTangentLineAndTheNearestVertex) {
  const auto plus = make_method("crest_feature_plus");
  const auto& p = dynamic_cast<const CrestFeatureMethod*>(plus.get())->crest_options();
  EXPECT_EQ(p.interpolation.control_points, crest_feature::ControlPoints::TangentLine);
  EXPECT_FALSE(p.feature_points.on_boundary_edges);
}

TEST(PaperDefaults, BrepGuidanceClosesByFigure4Only) {
  EXPECT_FALSE(BrepGuidanceOptions{}.later_closing_attempts);
  const MethodOptionValue off = false, on = true;
  const MethodOptions paper_options = make_method("brep_guidance")->options();
  const MethodOptions plus_options = make_method("brep_guidance_plus")->options();
  const MethodOptionValue* paper = paper_options.find("later_closing_attempts");
  const MethodOptionValue* plus = plus_options.find("later_closing_attempts");
  ASSERT_NE(paper, nullptr);
  ASSERT_NE(plus, nullptr);
  EXPECT_EQ(*paper, off);
  EXPECT_EQ(*plus, on);
}

TEST(PaperDefaults, EveryVariantIsListedOnceAfterItsPaperMethodsAlphabetically) {
  std::set<std::string> ids;
  for (const auto& m : make_all_methods())
    EXPECT_TRUE(ids.insert(m->id()).second) << m->id();
  for (const auto& m : make_methods_run_by_name())
    EXPECT_TRUE(ids.insert(m->id()).second) << m->id();
  for (const char* id : {"brep_guidance_plus", "slice_loft_plus", "slice_direct_plus",
                         "crest_feature_plus", "brep_guidance_segmented"})
    EXPECT_EQ(ids.count(id), 1u) << id;
  // The leaderboard sorts rows by id: a paper's row comes before its variant's.
  EXPECT_LT(std::string("slice_loft"), std::string("slice_loft_plus"));
}

}  // namespace
}  // namespace holebench
