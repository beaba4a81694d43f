// harness/run/case_pattern.h: what a pattern matches, and the regressions found by the fuzz
// target fuzz_case_pattern (tests/fuzz/case_pattern_fuzzer.cpp), each with the input that
// found it.
#include "harness/run/case_pattern.h"

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

// Found by fuzz_case_pattern (input "**/*a*\n*li?sodmall"): a '*' in the pattern was taken as
// the literal character where the text held a '*' too, and the match could not backtrack to
// it: "*" did not match "*li?sodmall". A '*' is now always a wildcard.
TEST(CasePattern, AStarMatchesATextThatHoldsAStar) {
  EXPECT_TRUE(wildcard_match("*", "*li?sodmall"));
  EXPECT_TRUE(wildcard_match("a*b", "a*xb"));
  EXPECT_TRUE(wildcard_match("*a", "*ba"));
  EXPECT_TRUE(wildcard_match("**/*a*", "**/*a*"));
}

// The properties the fuzz target checks, on a few inputs.
TEST(CasePattern, EveryTextMatchesItselfAndStar) {
  for (const std::string text : {"", "*", "?", "box/corner", "a*?b", "**"}) {
    EXPECT_TRUE(wildcard_match(text, text)) << text;
    EXPECT_TRUE(wildcard_match("*", text)) << text;
    EXPECT_TRUE(wildcard_match(text + "*", text)) << text;
  }
}

}  // namespace
}  // namespace holebench::harness
