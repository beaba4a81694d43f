#include "harness/results/results_reader.h"

#include "core/errors.h"
#include "harness/results/json_fields.h"
#include "harness/results/record_json.h"

#include <algorithm>
#include <fstream>
#include <sstream>

namespace holebench::harness {

nlohmann::json read_results_document(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InvalidInputError(path.string() + ": cannot open the results file");
  std::ostringstream text;
  text << in.rdbuf();
  nlohmann::json j;
  try {
    j = parse_json_naming_field(text.str());
  } catch (const std::exception& e) {
    throw InvalidInputError(path.string() + ": not a JSON results file: " + e.what());
  }
  if (!j.is_object() || !j.contains("results") || !j["results"].is_array()) {
    throw InvalidInputError(path.string() + ": no \"results\" array: not a holebench results file");
  }
  return j;
}

ResultsData read_results_json(const std::filesystem::path& path) {
  const nlohmann::json j = read_results_document(path);
  ResultsData data;
  if (j.contains("context")) {
    try {
      data.context = context_from_json(j["context"]);
    } catch (const std::exception& e) {
      throw InvalidInputError(path.string() + ": " + e.what());
    }
  }
  std::map<std::string, std::size_t> first_index;  // job id -> its first record
  std::size_t index = 0;
  for (const auto& record : j["results"]) {
    const std::string where = path.string() + ": record " + std::to_string(index);
    try {
      data.records.push_back(record_from_json(record));
    } catch (const std::exception& e) {
      throw InvalidInputError(where + ": " + e.what());
    }
    const std::string id = data.records.back().job.id();
    if (const auto [it, first] = first_index.emplace(id, index); !first) {
      throw InvalidInputError(where + ": field \"job_id\": '" + id + "' is record " +
                              std::to_string(it->second) + "'s too (a job id appears once)");
    }
    ++index;
  }
  return data;
}

}  // namespace holebench::harness
