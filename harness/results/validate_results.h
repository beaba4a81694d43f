// `holebench validate`: whether a results file holds numbers a reader can trust, record by
// record. The checks are computed as data (a list of violations, each naming its job) and
// printed separately; the rules are listed in docs/results.md ("Validation").
//
// Checked: the context's schema version; the fields every record has; job ids unique across
// the files (and equal to the id of the record's fields); every metric a finite number in the
// range its name promises (`_fraction` in [0, 1], `_ok` / `is_` flags 0 or 1, `_count` a
// non-negative integer); interval metrics ordered, lower <= value <= upper, all >= 0 for
// lengths; the distances in the order that holds for any pair of surfaces, mean <= RMS <=
// Hausdorff (upper end), and the new vertices' mean error below the hole's Hausdorff upper
// end; a job with status ok leaves no hole open that it does not guide.
#pragma once

#include "harness/results/record.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct ValidationOptions {
  /// Slack of the comparisons between two different metrics (mean <= RMS <= Hausdorff upper,
  /// new-vertex error <= hole Hausdorff upper), for round-off in their separate computations:
  /// a <= b passes when a <= b + slack * max(|a|, |b|). The bounds of one metric family
  /// (lower <= value <= upper) are compared exactly.
  double cross_metric_relative_slack = 1e-12;
};

/// One thing wrong in a results file.
struct Violation {
  std::string file;    ///< the results file; empty for a record checked in memory
  std::string job_id;  ///< as written (else "record N", 0-based); empty: the file's context
  /// The check, a stable name: schema_version, required_field, status, duplicate_job_id,
  /// field_type, job_id_mismatch, metrics_missing, finite, fraction_range, flag_value, count_value,
  /// interval, distance_order, new_vertex_error, chamfer, valid_repair, open_hole.
  std::string check;
  std::string message;  ///< what is wrong, with the values (written to read back exactly)
};

struct ValidationReport {
  std::size_t records = 0;  ///< records checked, over every file
  std::vector<Violation> violations;
  bool ok() const { return violations.empty(); }
};

/// The violations of one record's metrics and holes (finite, ranges, intervals, distance
/// order, open holes); `job_id` is the record's (`record.job.id()`), `file` empty.
std::vector<Violation> validate_record(const JobRecord& record,
                                       const ValidationOptions& options = {});

/// Checks every record of the results.json files `paths` (job ids unique across them).
/// Throws InvalidInputError naming the file when a file cannot be read as a results file
/// (read_results_document).
ValidationReport validate_results_files(const std::vector<std::filesystem::path>& paths,
                                        const ValidationOptions& options = {});

/// "FILE: JOB_ID: message [check]" (the file's context: "FILE: context: ...").
std::string format_violation(const Violation& violation);

/// "N records, M violations".
std::string format_validation_summary(const ValidationReport& report);

}  // namespace holebench::harness
