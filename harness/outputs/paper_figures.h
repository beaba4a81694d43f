// `holebench figures`: the papers' figures and tables on holebench's cases.
//  (a) figure 5 of the B-Rep paper: the four k = 3 inner convexity cases, guidance arrows
//      above (the large holes) and the closed models below (the small ones), rendered from
//      brep_guidance run on the cases (deterministic, so no results file is needed);
//  (b) Table 2 of the slice paper on the CAD cases: per model, input triangles, new
//      triangles, mean new-vertex error of slice_loft, slice_direct and liepa_cgal, per noise
//      level, from a results file;
//  (c) the crest-line paper's figures 10 and 13 setting: holes across 1, 2 and 3 creases of
//      the fandisk, per method and user mode, from a results file.
// The same inputs give the same bytes.
#pragma once

#include "harness/results/results_reader.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct FiguresOptions {
  std::filesystem::path out_dir;
  std::optional<std::filesystem::path> results;  ///< a results.json (the paper suite's)
  int tile_width = 400;
  int tile_height = 300;
};

/// Writes the figures and tables; returns the files written.
std::vector<std::filesystem::path> write_paper_figures(const FiguresOptions& options);

/// What `data` lacks for the tables (no CAD records for Table 2, no crease records for
/// figures 10/13, no records of a compared method): one sentence each, empty when nothing
/// is missing. A table without its records is still written, saying so.
std::vector<std::string> paper_figure_gaps(const ResultsData& data);

}  // namespace holebench::harness
