// The table `holebench run` prints when it is done: one Markdown row per job, then a line with
// the counts, the wall time and where the results are.
#pragma once

#include "harness/run/run_jobs.h"

#include <string>

namespace holebench::harness {

/// Columns: case, method, noise %, status, hole Hausdorff distance (`hausdorff_rel_diag`,
/// 3 significant digits), new faces (`new_faces_count`), method time in ms (1 decimal);
/// a metric the record does not have is "-". Starts with an empty line.
std::string format_run_summary(const RunSummary& summary);

}  // namespace holebench::harness
