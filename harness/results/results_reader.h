// Reading results files back (results.json as written by results_file.h, or records.jsonl
// as the runner appends them), for merge, compare, report and figures. One record's JSON
// text, both ways: harness/results/record_json.h; merging: harness/results/merge_results.h.
#pragma once

#include "harness/results/record.h"
#include "harness/results/results_file.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct ResultsData {
  RunContext context;
  std::vector<JobRecord> records;
};

/// Reads a results.json. Unknown fields are ignored; a missing field takes its default.
/// Throws InvalidInputError naming the file for unreadable or malformed content.
ResultsData read_results_json(const std::filesystem::path& path);

/// The JSON document of a results.json, as read_results_json reads it: an object with a
/// "results" array (records not yet checked). Throws InvalidInputError naming the file when it
/// cannot be opened, is not JSON or has no "results" array.
nlohmann::json read_results_document(const std::filesystem::path& path);

}  // namespace holebench::harness
