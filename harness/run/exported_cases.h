// Cases as `holebench cases export` wrote them (one folder per case: case.json, input.ply,
// complete.ply), found again under folders, as the jobs that score a method's repairs of them
// (`holebench evaluate --cases`, harness/run/scored_repairs.h).
#pragma once

#include "harness/results/record.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// One exported case: what its case.json names.
struct ExportedCase {
  std::string id;
  std::uint64_t seed = 0;
  double noise_percent = 0.0;
  std::filesystem::path dir;    ///< the folder holding case.json
  std::filesystem::path input;  ///< its holed mesh (case.json's files.input)
};

/// Every case.json under `roots` (each a folder searched to any depth, or a case.json file), in
/// path order. Throws InvalidInputError naming the file for a missing root, an unreadable
/// case.json or one without an id, and where no case is found.
std::vector<ExportedCase> find_exported_cases(const std::vector<std::filesystem::path>& roots);

/// The job of scoring `method`'s repair of `exported` for `user`.
Job scoring_job(const ExportedCase& exported, const std::string& method, const std::string& user);

}  // namespace holebench::harness
