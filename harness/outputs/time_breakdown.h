// Where a run's worker time went, from its records' timings: the worker-seconds of each stage
// (`stages_s`), of each step of the evaluation (`evaluation_phases_s`) and of each method,
// and the ratio of the time outside the method calls to the methods' own. `holebench timing`
// prints it; the README's nightly table and the speed figures of docs/ are read off it.
#pragma once

#include "harness/results/record.h"

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace holebench::harness {

/// A name and its worker-seconds summed over the records, with the number of records that
/// have it.
struct TimeTotal {
  std::string name;
  double seconds = 0.0;
  std::size_t records = 0;
};

struct TimeBreakdown {
  std::size_t records = 0;
  // Each list from the most worker-seconds to the fewest (equal ones by name): a results file
  // read back has its records' timings in the order of their names, not as they ran.
  std::vector<TimeTotal> stages;             ///< by stage
  std::vector<TimeTotal> evaluation_phases;  ///< by step of the evaluation
  std::vector<TimeTotal> methods;            ///< the "method" stage by method
  double total_seconds = 0.0;                ///< every stage of every record
  double method_seconds = 0.0;               ///< the "method" stage
  double heap_warmup_seconds = 0.0;
  /// Everything but the method calls, over the methods' own time (0 where the methods took
  /// none): the "outside / methods"; and the same without the heap warm-up.
  double outside_over_methods = 0.0;
  double outside_over_methods_without_warmup = 0.0;
};

TimeBreakdown time_breakdown(const std::vector<JobRecord>& records);

/// Markdown: a line with the records' count and worker time, the ratios, then a table for the
/// stages, one for the evaluation's steps (share of the "evaluation" stage) and one for the
/// methods (share of the "method" stage). Seconds with one decimal, shares in whole percent.
std::string format_time_breakdown(const TimeBreakdown& breakdown);

}  // namespace holebench::harness
