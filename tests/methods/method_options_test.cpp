#include "methods/method_options.h"
#include "methods/registry.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <variant>

namespace holebench {
namespace {

// The settings of `a` whose value in `b` differs or is missing (both lists have the same names
// for one method class).
std::set<std::string> differing_settings(const MethodOptions& a, const MethodOptions& b) {
  std::set<std::string> names;
  for (const auto& option : a.values()) {
    const MethodOptionValue* other = b.find(option.name);
    if (!other || *other != option.value)
      names.insert(option.name);
  }
  return names;
}

TEST(MethodOptions, NestedSettingsAreNamedUnderTheirStruct) {
  MethodOptions inner;
  inner.add("max_depth", 2).add("enabled", true);
  MethodOptions outer;
  outer.add("refine_and_fair", false).add("planarity_split", inner).add("ratio", 0.5);
  ASSERT_EQ(outer.values().size(), 4u);
  EXPECT_EQ(outer.values()[1].name, "planarity_split.max_depth");
  EXPECT_EQ(std::get<std::int64_t>(outer.values()[1].value), 2);
  EXPECT_EQ(outer.values()[2].name, "planarity_split.enabled");
  EXPECT_TRUE(std::get<bool>(*outer.find("planarity_split.enabled")));
  EXPECT_EQ(std::get<double>(*outer.find("ratio")), 0.5);
  EXPECT_EQ(outer.find("max_depth"), nullptr);
}

// Every built-in method reports its settings, each name once.
TEST(MethodOptions, EveryBuiltInMethodReportsItsSettingsOnce) {
  for (auto* list : {make_all_methods, make_methods_run_by_name}) {
    for (const auto& method : list()) {
      const MethodOptions options = method->options();
      EXPECT_FALSE(options.empty()) << method->id();
      std::set<std::string> names;
      for (const auto& option : options.values())
        EXPECT_TRUE(names.insert(option.name).second) << method->id() << ": " << option.name;
    }
  }
}

// The variants of one class differ in exactly the setting that makes them variants, so their
// records can be told apart by their options as well as by their ids.
TEST(MethodOptions, VariantsDifferInTheSettingThatMakesThem) {
  EXPECT_EQ(differing_settings(make_method("slice_loft")->options(),
                               make_method("slice_direct")->options()),
            std::set<std::string>{"tessellation.direct"});
  EXPECT_EQ(differing_settings(make_method("brep_guidance")->options(),
                               make_method("brep_guidance_segmented")->options()),
            std::set<std::string>{"faces"});
  EXPECT_EQ(std::get<std::string>(*make_method("brep_guidance_segmented")->options().find("faces")),
            "segmentation");
}

TEST(MethodOptions, FindMethodGivesNullForAnUnknownId) {
  EXPECT_EQ(find_method("no_such_method"), nullptr);
  ASSERT_NE(find_method("crest_feature"), nullptr);
  EXPECT_EQ(find_method("crest_feature")->id(), "crest_feature");
  EXPECT_THROW(make_method("no_such_method"), std::invalid_argument);
}

}  // namespace
}  // namespace holebench
