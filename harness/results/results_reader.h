// Reading results files back (results.json as written by results_file.h, or records.jsonl
// as the runner appends them), for merge, compare, report and figures.
#pragma once

#include "harness/results/results_file.h"
#include "harness/run/job.h"

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

/// One record from its JSON object (as written by write_results_json).
JobRecord record_from_json_text(const std::string& json_text);

/// The JSON text of one record (one line, as the runner appends it to records.jsonl).
std::string record_to_json_line(const JobRecord& record);

/// A record's snapshot path (relative to the folder `from_dir` of its results file) made
/// relative to `to_dir`, where a merged results file goes; empty stays empty.
std::string snapshot_relative_to(const std::string& snapshot, const std::filesystem::path& from_dir,
                                 const std::filesystem::path& to_dir);

/// Merges result sets: records matched by job id; a later set's record replaces an earlier
/// one with the same id. The context is the first set's, with `suite` kept and the merge
/// noted. Records are ordered by job id.
ResultsData merge_results(const std::vector<ResultsData>& sets);

}  // namespace holebench::harness
