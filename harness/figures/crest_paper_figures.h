// The crest-line paper's figures on holebench's cases (`holebench figures`): figure 10 (the
// fandisk's holes across 1, 2 and 3 creases: the input with its crest lines, and the
// baselines that only close them), figure 13 (the same holes filled by crest_feature, with
// no user and with the oracle user, the patch in green and the feature lines drawn) and
// figure 12 (the concave corner hole).
#pragma once

#include "harness/figures/figure_sheet.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// The cases of figures 10 and 13 (holes across 1, 2, 3 creases) and of figure 12.
const std::vector<std::string>& crest_crease_cases();
const std::string& crest_concave_corner_case();

/// Renders the figures (running the methods on the cases, deterministic); returns the files
/// written (PNG, SVG, caption per figure).
std::vector<std::filesystem::path> write_crest_paper_figures(const PaperFigureOptions& options);

}  // namespace holebench::harness
