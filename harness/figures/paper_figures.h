// `holebench figures`: the papers' figures and tables on holebench's cases.
//  (a) figure 5 of the B-Rep paper: the four k = 3 inner convexity cases, guidance arrows
//      above (the large holes) and the closed models below (the small ones), rendered from
//      brep_guidance run on the cases (deterministic, so no results file is needed);
//  (b) Table 2 of the slice paper on the CAD cases: per model, input triangles, new
//      triangles, mean new-vertex error of slice_loft, slice_direct and liepa_cgal, per noise
//      level, from a results file;
//  (c) the crest-line paper's figures 10 and 13 setting: holes across 1, 2 and 3 creases of
//      the fandisk, per method and user mode, from a results file;
//  (d) the slice paper's figures 2, 17-20, 22, 23-24 rendered (slice_paper_figures.h), and
//      Table 2 with the paper's four rows beside ours (from a results file);
//  (e) the crest-line paper's figures 10, 12 and 13 rendered (crest_paper_figures.h).
// Pictures are rendered from the methods run on the cases (deterministic: the results the
// run's records measured); each has a caption file naming the run, the code and the cases.
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
  int tile_width = 400;                          ///< figure 5's tiles
  int tile_height = 300;
  int panel_size = 300;  ///< the square panels of the other figures
  int samples_per_axis = 2;
  /// Figures to render, by stem ("figure2", "figure5", "figure10", "figure12", "figure13",
  /// "figure17" .. "figure20", "figure22", "figure23" (with 24)); empty: all. Tables are
  /// written whenever `results` is given.
  std::vector<std::string> only;
};

/// The figure stems write_paper_figures knows, in its order.
const std::vector<std::string>& paper_figure_names();

/// Writes the figures and tables; returns the files written.
std::vector<std::filesystem::path> write_paper_figures(const FiguresOptions& options);

/// What `data` lacks for the tables (no CAD records for Table 2, no crease records for
/// figures 10/13, no records of a compared method): one sentence each, empty when nothing
/// is missing. A table without its records is still written, saying so.
std::vector<std::string> paper_figure_gaps(const ResultsData& data);

}  // namespace holebench::harness
