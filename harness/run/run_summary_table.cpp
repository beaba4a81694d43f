#include "harness/run/run_summary_table.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>

namespace holebench::harness {

std::string format_run_summary(const RunSummary& summary) {
  std::string text =
      "\n| case | method | noise % | status | hausdorff (rel. diag) | new faces | time (ms) |\n"
      "|---|---|---:|---|---:|---:|---:|\n";
  for (const auto& r : summary.records) {
    auto metric = [&](const char* name) {
      const double* value = r.metric(name);
      return value ? fmt::format("{:.3g}", *value) : std::string("-");
    };
    text += fmt::format("| {} | {} | {} | {} | {} | {} | {:.1f} |\n", r.job.case_id,
                        r.job.method_id, r.job.noise_percent, to_string(r.status),
                        metric(metric_names::kHausdorffRelDiag),
                        metric(metric_names::kNewFacesCount), 1000.0 * r.method_seconds);
  }
  text += fmt::format("\n{} jobs, {} not ok, {:.1f} s. Results: {} and {}\n",
                      summary.records.size(), summary.failures, summary.seconds,
                      summary.results_json.string(), summary.results_csv.string());
  return text;
}

}  // namespace holebench::harness
