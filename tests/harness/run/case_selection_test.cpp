#include "harness/run/case_selection.h"

#include <gtest/gtest.h>

namespace holebench::harness {
namespace {

TEST(SelectCases, PatternsSelectInCatalogOrderAndTyposAreErrors) {
  generators::CatalogOptions options;
  options.include_cad = false;
  const generators::CaseCatalog catalog(options);
  const auto selected = select_cases(catalog, {"box/corner", "box/edge"});
  ASSERT_EQ(selected.size(), 2u);
  EXPECT_EQ(selected[0].id, "box/edge");  // catalog order, not pattern order
  EXPECT_THROW(select_cases(catalog, {"box/corners"}), std::invalid_argument);
}

// A pattern that names a model the catalog skipped (here: the CAD data is missing) is not a
// typo: the rest of the selection still runs, and the catalog holds the reason.
TEST(SelectCases, ASkippedModelLeavesTheRestOfTheSelection) {
  generators::CatalogOptions options;
  options.cad_data_dir = "/nonexistent/holebench/cad";
  options.families = {"box", "cad"};
  const generators::CaseCatalog catalog(options);
  ASSERT_FALSE(catalog.skipped().empty());
  const auto selected = select_cases(catalog, {"cad/fandisk/*", "box/*", "cad/*/small"});
  ASSERT_EQ(selected.size(), 3u);
  for (const auto& c : selected)
    EXPECT_EQ(c.family, "box");
  EXPECT_THROW(select_cases(catalog, {"cad/no_such_model/*"}), std::invalid_argument);
}

}  // namespace
}  // namespace holebench::harness
