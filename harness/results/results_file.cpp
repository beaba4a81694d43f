#include "harness/results/results_file.h"

#include "core/atomic_file.h"
#include "harness/results/record_json.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace holebench::harness {

namespace {

std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"')
      quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

}  // namespace

void write_results_json(const std::filesystem::path& path, const RunContext& context,
                        const std::vector<JobRecord>& records) {
  nlohmann::ordered_json j;
  j["context"] = context_to_json(context);
  j["results"] = nlohmann::ordered_json::array();
  for (const auto& record : records)
    j["results"].push_back(record_to_json(record));
  write_file_atomically(path, [&j](std::ostream& out) { out << j.dump(2) << '\n'; });
}

void write_results_csv(const std::filesystem::path& path, const std::vector<JobRecord>& records) {
  write_file_atomically(path, [&records](std::ostream& out) {
    out << "job_id,case_id,method,user,seed,case_family,case_kind,noise_percent,status,metric,"
           "value\n";
    for (const auto& record : records) {
      const std::string prefix = fmt::format(
          "{},{},{},{},{},{},{},{},{}", csv_field(record.job.id()), csv_field(record.job.case_id),
          csv_field(record.job.method_id), csv_field(record.job.user), record.job.seed,
          csv_field(record.case_family), csv_field(record.case_kind), record.job.noise_percent,
          to_string(record.status));
      if (record.metrics.empty())
        out << prefix << ",,\n";
      // fmt's "{}" is the shortest text that reads back to the same double.
      for (const auto& metric : record.metrics) {
        out << prefix << ',' << metric.name << ',' << fmt::format("{}", metric.value) << '\n';
      }
    }
  });
}

}  // namespace holebench::harness
