// The results of a run: a context block (what produced them) plus one record per job,
// written as JSON (numbers as numbers) and as long-format CSV (one row per metric).
#pragma once

#include "harness/results/record.h"
#include "harness/results/run_context.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// Writes `dir/results.json`.
void write_results_json(const std::filesystem::path& path, const RunContext& context,
                        const std::vector<JobRecord>& records);

/// Writes the long-format CSV: job_id, case_id, method, seed, case_family, case_kind,
/// noise_percent, status, metric, value; a job without metrics has one row with an empty
/// metric.
void write_results_csv(const std::filesystem::path& path, const std::vector<JobRecord>& records);

}  // namespace holebench::harness
