#include "harness/case_selection.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

TEST(WildcardMatch, StarsAndQuestionMarks) {
  EXPECT_TRUE(wildcard_match("box/*", "box/corner"));
  EXPECT_TRUE(wildcard_match("*", ""));
  EXPECT_TRUE(wildcard_match("cad/*/small", "cad/fandisk/edge_convex/small"));
  EXPECT_FALSE(wildcard_match("cad/*/small", "cad/fandisk/edge_convex/large"));
  EXPECT_TRUE(wildcard_match("box/?dge", "box/edge"));
  EXPECT_FALSE(wildcard_match("box/edge", "box/edges"));
  EXPECT_TRUE(wildcard_match("*a*b*c", "xxaxxbxxc"));
  EXPECT_FALSE(wildcard_match("*a*b*c", "xxaxxcxxb"));
}

TEST(SelectCases, PatternsSelectInCatalogOrderAndTyposAreErrors) {
  generators::CatalogOptions options;
  options.include_cad = false;
  const generators::CaseCatalog catalog(options);
  const auto selected = select_cases(catalog, {"box/corner", "box/edge"});
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(selected[0].id, "box/edge");  // catalog order, not pattern order
  EXPECT_THROW(select_cases(catalog, {"box/corners"}), std::invalid_argument);
}

}  // namespace
}  // namespace holebench::harness
