// The slice paper's figures on holebench's cases (`holebench figures`): figure 2 (every step
// of the method, from its layers, on the corner hole of figure 17), figures 17-20 (the four
// models of Table 2: input, slice_loft, slice_direct), figure 22 (the patch under 5 % and
// 25 % noise), figures 23-24 (the cone apex: input, top view, slices; recovered apex, final
// output); and Table 2 with the paper's four rows and its numbers beside ours.
#pragma once

#include "harness/figures/figure_sheet.h"
#include "harness/results/results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// A row of the slice paper's Table 2: the paper's model, the holebench case that stands for
/// it, and the paper's own figures (its units: model units, errors times 1e3).
struct SliceTable2Model {
  std::string figure;  ///< "Figure 17"
  std::string what;    ///< the paper's description
  std::string case_id;
  int paper_input_triangles = 0;
  int paper_new_triangles = 0;
  double paper_loft_error_e3 = 0.0;    ///< slice_loft's column, x 1e-3 model units
  double paper_direct_error_e3 = 0.0;  ///< slice_direct's column
};
const std::vector<SliceTable2Model>& slice_table_2_models();

/// The case of figures 23-24 (a cone's apex).
const std::string& slice_cone_apex_case();

/// Renders the figures (running slice_loft and slice_direct on the cases, deterministic);
/// returns the files written (PNG, SVG, caption per figure).
std::vector<std::filesystem::path> write_slice_paper_figures(const PaperFigureOptions& options);

/// Table 2 with the paper's rows (markdown and LaTeX) from `data`'s records at noise 0: per
/// model, the paper's input and new triangles and its two errors; ours: input and new
/// triangles (slice_loft), the mean new-vertex error of slice_loft and slice_direct in model
/// units x 1e3 (the paper's) and relative to the diagonal, and the baselines' (liepa_cgal,
/// cgal_triangulate, occt_fill, meshlab_close_holes) relative errors. A method without a record (or
/// without new vertices) shows "-" and its status.
std::vector<std::filesystem::path> write_slice_table_2_paper_rows(
    const ResultsData& data, const std::filesystem::path& out_dir);

}  // namespace holebench::harness
