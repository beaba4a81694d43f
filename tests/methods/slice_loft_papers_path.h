// Shared check of the slice_loft tests: a case with one hole is closed on the paper's path.
#pragma once

#include "generators/case_catalog.h"
#include "methods/slice_loft/slice_loft.h"
#include "methods/slice_loft/slice_loft_variants.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench {

/// Runs slice_loft (or with `options`, e.g. slice_loft::plus_options) on the case (one hole) and
/// checks that the hole is closed without a fallback, that no boundary edge is left, and that the
/// hole's note says `note_says`.
inline void expect_closed_on_the_papers_path(const std::string& case_id,
                                             const std::string& note_says,
                                             const SliceLoftOptions& options = {}) {
  const Case c = generators::make_case(case_id);
  const MethodResult result = run_slice_loft(c.input, options);
  ASSERT_EQ(result.holes.size(), 1u) << case_id;
  const HoleReport& hole = result.holes[0];
  EXPECT_TRUE(hole.closed) << case_id << ": " << hole.note;
  EXPECT_EQ(hole.fallback, "") << case_id << ": " << hole.note;
  for (auto e : result.repaired.edges())
    EXPECT_FALSE(result.repaired.is_boundary(e)) << case_id;
  EXPECT_NE(hole.note.find(note_says), std::string::npos) << case_id << ": " << hole.note;
}

}  // namespace holebench
