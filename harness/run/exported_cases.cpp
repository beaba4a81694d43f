#include "harness/run/exported_cases.h"

#include "core/errors.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

namespace holebench::harness {

namespace {

namespace fs = std::filesystem;

ExportedCase read_exported_case(const fs::path& case_json) {
  std::ifstream in(case_json);
  if (!in)
    throw InvalidInputError(case_json.string() + ": cannot be read");
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInputError(case_json.string() + ": not JSON: " + e.what());
  }
  ExportedCase exported;
  exported.dir = case_json.parent_path();
  try {
    exported.id = j.at("id").get<std::string>();
    exported.seed = j.value("seed", std::uint64_t{0});
    exported.noise_percent = j.value("noise_percent", 0.0);
    std::string input = "input.ply";
    if (j.contains("files") && j["files"].contains("input"))
      input = j["files"]["input"].get<std::string>();
    exported.input = exported.dir / input;
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInputError(case_json.string() + ": not a case export (" + e.what() + ")");
  }
  return exported;
}

}  // namespace

std::vector<ExportedCase> find_exported_cases(const std::vector<fs::path>& roots) {
  std::vector<fs::path> files;
  for (const auto& root : roots) {
    std::error_code error;
    if (fs::is_regular_file(root, error)) {
      files.push_back(root);
      continue;
    }
    if (!fs::is_directory(root, error))
      throw InvalidInputError(root.string() + ": no such folder of exported cases");
    for (const auto& entry : fs::recursive_directory_iterator(root)) {
      if (entry.is_regular_file() && entry.path().filename() == "case.json")
        files.push_back(entry.path());
    }
  }
  std::sort(files.begin(), files.end());
  std::vector<ExportedCase> cases;
  for (const auto& file : files)
    cases.push_back(read_exported_case(file));
  if (cases.empty()) {
    throw InvalidInputError(
        "no case.json under the --cases folders (write them with `holebench cases export`)");
  }
  return cases;
}

Job scoring_job(const ExportedCase& exported, const std::string& method, const std::string& user) {
  Job job;
  job.case_id = exported.id;
  job.method_id = method;
  job.noise_percent = exported.noise_percent;
  job.seed = exported.seed;
  job.user = user;
  return job;
}

}  // namespace holebench::harness
