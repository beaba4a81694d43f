#include "harness/outputs/time_breakdown.h"

#include <fmt/format.h>

#include <algorithm>

namespace holebench::harness {

namespace {

void add_to(std::vector<TimeTotal>& totals, const std::string& name, double seconds) {
  auto it = std::find_if(totals.begin(), totals.end(),
                         [&](const TimeTotal& total) { return total.name == name; });
  if (it == totals.end()) {
    totals.push_back({name, 0.0, 0});
    it = totals.end() - 1;
  }
  it->seconds += seconds;
  ++it->records;
}

double seconds_of(const std::vector<TimeTotal>& totals, const std::string& name) {
  for (const auto& total : totals) {
    if (total.name == name)
      return total.seconds;
  }
  return 0.0;
}

void sort_by_seconds(std::vector<TimeTotal>& totals) {
  std::sort(totals.begin(), totals.end(), [](const TimeTotal& a, const TimeTotal& b) {
    return a.seconds != b.seconds ? a.seconds > b.seconds : a.name < b.name;
  });
}

double ratio(double part, double whole) {
  return whole > 0.0 ? part / whole : 0.0;
}

// One table: name, worker-s, share of `whole`, records that have it.
std::string format_table(const char* heading, const char* first_column,
                         const std::vector<TimeTotal>& totals, double whole, const char* share_of) {
  if (totals.empty())
    return "";
  std::string text = fmt::format(
      "\n{}\n\n| {} | worker-s | share of {} | records |\n"
      "|---|---:|---:|---:|\n",
      heading, first_column, share_of);
  for (const auto& total : totals)
    text += fmt::format("| {} | {:.1f} | {:.0f} % | {} |\n", total.name, total.seconds,
                        100.0 * ratio(total.seconds, whole), total.records);
  return text;
}

}  // namespace

TimeBreakdown time_breakdown(const std::vector<JobRecord>& records) {
  TimeBreakdown breakdown;
  breakdown.records = records.size();
  for (const auto& record : records) {
    for (const auto& stage : record.stages) {
      add_to(breakdown.stages, stage.phase, stage.seconds);
      breakdown.total_seconds += stage.seconds;
      if (stage.phase == stage_names::kMethod)
        add_to(breakdown.methods, record.job.method_id, stage.seconds);
    }
    for (const auto& phase : record.evaluation_phases)
      add_to(breakdown.evaluation_phases, phase.phase, phase.seconds);
  }
  sort_by_seconds(breakdown.stages);
  sort_by_seconds(breakdown.evaluation_phases);
  sort_by_seconds(breakdown.methods);
  breakdown.method_seconds = seconds_of(breakdown.stages, stage_names::kMethod);
  breakdown.heap_warmup_seconds = seconds_of(breakdown.stages, stage_names::kHeapWarmup);
  const double outside = breakdown.total_seconds - breakdown.method_seconds;
  breakdown.outside_over_methods = ratio(outside, breakdown.method_seconds);
  breakdown.outside_over_methods_without_warmup =
      ratio(outside - breakdown.heap_warmup_seconds, breakdown.method_seconds);
  return breakdown;
}

std::string format_time_breakdown(const TimeBreakdown& breakdown) {
  std::string text = fmt::format(
      "{} records, {:.1f} worker-s. Outside the method calls / the methods' own: {:.2f}x "
      "({:.2f}x without the heap warm-up)\n",
      breakdown.records, breakdown.total_seconds, breakdown.outside_over_methods,
      breakdown.outside_over_methods_without_warmup);
  text += format_table("Stages (`stages_s`)", "stage", breakdown.stages, breakdown.total_seconds,
                       "all");
  text +=
      format_table("Evaluation steps (`evaluation_phases_s`)", "step", breakdown.evaluation_phases,
                   seconds_of(breakdown.stages, stage_names::kEvaluation), "evaluation");
  text += format_table("Methods (the `method` stage)", "method", breakdown.methods,
                       breakdown.method_seconds, "methods");
  return text;
}

}  // namespace holebench::harness
