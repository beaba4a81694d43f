// The slice paper's Table 2 settled by ablation (`holebench figures`, table2_ablation.md):
// slice_loft against slice_direct with the paper's steps, with each of the project's
// departures alone (slice_loft_with_<d> against slice_direct_with_<d>), and with all of them
// (slice_loft_plus against slice_direct_plus), per noise level, on three measures.
#pragma once

#include "harness/results/results_reader.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// One comparison of the ablation: a loft method against its direct counterpart.
struct SliceAblationPair {
  std::string setting;  ///< "paper's steps", a departure's name, or "all departures"
  std::string loft, direct;
};

/// The pairs in table order: the paper's steps, each departure alone, all of them.
std::vector<SliceAblationPair> slice_ablation_pairs();

/// One row: a pair, a noise level and a measure, over the jobs (same case, noise, seed and
/// user) on which both methods have the measure.
struct SliceAblationRow {
  SliceAblationPair pair;
  double noise_percent = 0.0;
  std::string measure;
  std::size_t holes = 0;     ///< jobs with the measure on both sides, each the method's own
  std::size_t left_out = 0;  ///< jobs on both sides where either failed or used a fallback
  double loft_median = 0.0;  ///< over those jobs
  double direct_median = 0.0;
  std::size_t loft_better = 0;    ///< jobs where the loft's value is lower
  std::size_t direct_better = 0;  ///< jobs where the direct value is lower
  double p_value = 1.0;           ///< two-sided Wilcoxon signed-rank, loft - direct
};

/// Every row the records allow (a pair without a job on both sides has no row).
std::vector<SliceAblationRow> slice_ablation_rows(const ResultsData& data);

/// Writes table2_ablation.md from `data` (the suite slice_ablation's results, or any results
/// with the pairs' methods); returns the file written.
std::vector<std::filesystem::path> write_slice_ablation_table(const ResultsData& data,
                                                              const std::filesystem::path& out_dir);

}  // namespace holebench::harness
