#include "harness/results/validate_results.h"

#include "harness/results/record_json.h"
#include "harness/results/results_file.h"
#include "harness/results/results_reader.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

namespace holebench::harness {
namespace {

// A built-in method's settings (flags, numbers, names) or an external method's command.
bool method_options_are_valid(const nlohmann::json& options) {
  if (!options.is_object())
    return false;
  if (const auto command = options.find("command"); command != options.end()) {
    const auto tolerance = options.find("vertex_tolerance_rel_diag");
    return command->is_string() && (tolerance == options.end() || tolerance->is_number());
  }
  for (const auto& [key, value] : options.items()) {
    if (!value.is_boolean() && !value.is_number() && !value.is_string())
      return false;
  }
  return true;
}

using Report = std::function<void(const char* check, std::string message)>;

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool starts_with(const std::string& text, const std::string& prefix) {
  return text.rfind(prefix, 0) == 0;
}

/// A number as written in results files: the shortest text that reads back to it.
std::string number(double value) {
  return fmt::format("{}", value);
}

std::string named(const std::string& name, double value) {
  return name + " = " + number(value);
}

// --- one record's metrics and holes --------------------------------------------------------

// Each metric in the range its name promises (docs/metrics.md: units are in the names).
void check_ranges(const std::map<std::string, double>& metrics, const Report& report) {
  for (const auto& [name, value] : metrics) {
    if (ends_with(name, "_fraction") && !(value >= 0.0 && value <= 1.0))
      report("fraction_range", named(name, value) + " is outside [0, 1]");
    if ((ends_with(name, "_ok") || starts_with(name, "is_")) && value != 0.0 && value != 1.0)
      report("flag_value", named(name, value) + " is a flag but neither 0 nor 1");
    if (ends_with(name, "_count") && !(value >= 0.0 && value == std::floor(value)))
      report("count_value", named(name, value) + " is not a non-negative integer");
  }
}

// A metric family <stem>_<unit> with its bounds <stem>_lower_<unit> and <stem>_upper_<unit>.
struct Interval {
  std::string value_name;
  std::optional<std::string> lower_name, upper_name;
};

// The families of the bounds among `metrics`, by the value's name.
std::map<std::string, Interval> intervals(const std::map<std::string, double>& metrics) {
  std::map<std::string, Interval> families;
  for (const auto& [name, value] : metrics) {
    for (const std::string marker : {"_lower_", "_upper_"}) {
      const auto at = name.rfind(marker);
      if (at == std::string::npos || at == 0)
        continue;
      const std::string value_name = name.substr(0, at) + "_" + name.substr(at + marker.size());
      Interval& family = families[value_name];
      family.value_name = value_name;
      (marker == "_lower_" ? family.lower_name : family.upper_name) = name;
    }
  }
  return families;
}

// lower <= value <= upper, exactly (the bounds of one computation); lengths are >= 0. A family
// whose value is among `unusable` (not a finite number: reported already) is left out.
void check_intervals(const std::map<std::string, double>& metrics,
                     const std::set<std::string>& unusable, const Report& report) {
  for (const auto& [value_name, family] : intervals(metrics)) {
    if (unusable.count(value_name))
      continue;
    const auto value = metrics.find(value_name);
    const bool has_value = value != metrics.end();
    if (!has_value) {
      report("interval", (family.upper_name ? *family.upper_name : *family.lower_name) +
                             " is a bound of " + value_name + ", which is missing");
    }
    const double lower = family.lower_name ? metrics.at(*family.lower_name) : 0.0;
    const double upper = family.upper_name ? metrics.at(*family.upper_name) : 0.0;
    if (family.lower_name && has_value && !(lower <= value->second)) {
      report("interval", named(*family.lower_name, lower) + " > " +
                             named(value_name, value->second) + " (lower <= value)");
    }
    if (family.upper_name && has_value && !(value->second <= upper)) {
      report("interval", named(value_name, value->second) + " > " +
                             named(*family.upper_name, upper) + " (value <= upper)");
    }
    if (family.lower_name && family.upper_name && !has_value && !(lower <= upper)) {
      report("interval", named(*family.lower_name, lower) + " > " +
                             named(*family.upper_name, upper) + " (lower <= upper)");
    }
    // A length or a squared length: the interval lies in [0, inf).
    if (ends_with(value_name, "_rel_diag") || ends_with(value_name, "_rel_diag2")) {
      for (const auto& name :
           {family.lower_name, std::optional<std::string>(value_name), family.upper_name}) {
        const auto it = name ? metrics.find(*name) : metrics.end();
        if (it != metrics.end() && !(it->second >= 0.0))
          report("interval", named(it->first, it->second) + " is negative (a distance)");
      }
    }
  }
}

// a <= b up to the relative slack (two separate computations).
bool at_most(double a, double b, double slack) {
  return a <= b + slack * std::max(std::fabs(a), std::fabs(b));
}

// For any two surfaces mean <= RMS <= Hausdorff (each direction, hence their maxima), and the
// patch's new vertices lie on the patch: their mean distance is at most the hole's Hausdorff.
void check_distance_order(const std::map<std::string, double>& metrics,
                          const ValidationOptions& options, const Report& report) {
  const double slack = options.cross_metric_relative_slack;
  for (const std::string prefix : {"", "hole_"}) {
    std::vector<std::string> chain;
    for (const char* name : {metric_names::kMeanDistanceRelDiag, metric_names::kRmsDistanceRelDiag,
                             metric_names::kHausdorffUpperRelDiag}) {
      if (metrics.count(prefix + name))
        chain.push_back(prefix + name);
    }
    for (std::size_t i = 0; i + 1 < chain.size(); ++i) {
      const double a = metrics.at(chain[i]), b = metrics.at(chain[i + 1]);
      if (!at_most(a, b, slack)) {
        report("distance_order",
               named(chain[i], a) + " > " + named(chain[i + 1], b) + " (mean <= RMS <= Hausdorff)");
      }
    }
  }
  const auto error = metrics.find(metric_names::kNewVertexMeanErrorRelDiag);
  const auto hausdorff = metrics.find(metric_names::kHoleHausdorffUpperRelDiag);
  if (error != metrics.end() && hausdorff != metrics.end() &&
      !at_most(error->second, hausdorff->second, slack)) {
    report("new_vertex_error", named(error->first, error->second) + " > " +
                                   named(hausdorff->first, hausdorff->second) +
                                   " (new vertices lie on the patch)");
  }
}

// Chamfer-L1 is the average of the two directed mean distances, the mean distance their
// larger; likewise Chamfer-L2 and the squared RMS distance (metrics/literature_metrics.h).
void check_chamfer(const std::map<std::string, double>& metrics, const ValidationOptions& options,
                   const Report& report) {
  const double slack = options.cross_metric_relative_slack;
  for (const std::string prefix : {"", "hole_"}) {
    const auto l1 = metrics.find(prefix + metric_names::kChamferL1RelDiag);
    const auto mean = metrics.find(prefix + metric_names::kMeanDistanceRelDiag);
    if (l1 != metrics.end() && mean != metrics.end() && !at_most(l1->second, mean->second, slack)) {
      report("chamfer", named(l1->first, l1->second) + " > " + named(mean->first, mean->second) +
                            " (the average of two directed means is at most their larger)");
    }
    const auto l2 = metrics.find(prefix + metric_names::kChamferL2RelDiag2);
    const auto rms = metrics.find(prefix + metric_names::kRmsDistanceRelDiag);
    if (l2 != metrics.end() && rms != metrics.end() &&
        !at_most(l2->second, rms->second * rms->second, slack)) {
      report("chamfer", named(l2->first, l2->second) + " > " + rms->first +
                            "^2 = " + number(rms->second * rms->second) +
                            " (the average of two mean squares is at most their larger)");
    }
  }
}

// valid_repair_ok = 1 promises a closed, manifold, consistently oriented output without a
// self-intersection that involves a new face, the input away from the holes unchanged and
// every hole closed (docs/results.md, "Valid repair").
void check_valid_repair(const JobRecord& record, const std::map<std::string, double>& metrics,
                        const Report& report) {
  const auto valid = metrics.find(metric_names::kValidRepairOk);
  if (valid == metrics.end() || valid->second != 1.0)
    return;
  for (const char* flag :
       {metric_names::kIsClosed, metric_names::kIsManifold, metric_names::kIsConsistentlyOriented,
        metric_names::kOriginalFacesUnchangedOk}) {
    const auto it = metrics.find(flag);
    if (it == metrics.end() || it->second != 1.0) {
      report("valid_repair",
             std::string("valid_repair_ok = 1 but ") + flag +
                 (it == metrics.end() ? " is missing" : " = " + number(it->second)));
    }
  }
  const auto crossings = metrics.find(metric_names::kPatchSelfIntersectionsCount);
  if (crossings == metrics.end() || crossings->second != 0.0) {
    report("valid_repair",
           std::string("valid_repair_ok = 1 but ") + metric_names::kPatchSelfIntersectionsCount +
               (crossings == metrics.end() ? " is missing" : " = " + number(crossings->second)));
  }
  for (const auto& hole : record.holes) {
    if (!hole.closed) {
      report("valid_repair",
             fmt::format("valid_repair_ok = 1 but hole {} is open", hole.hole_index));
    }
  }
}

// --- the JSON of a record --------------------------------------------------------------------

void check_context(const nlohmann::json& document, const Report& report) {
  const auto context = document.find("context");
  if (context == document.end() || !context->is_object()) {
    report("schema_version", "no \"context\" object");
    return;
  }
  const auto version = context->find("schema_version");
  if (version == context->end() || !version->is_number_integer()) {
    report("schema_version", "no integer \"schema_version\" in the context");
  } else if (version->get<long long>() != kResultsSchemaVersion) {
    report("schema_version", fmt::format("schema_version {} is not the one this holebench "
                                         "writes and reads ({})",
                                         version->dump(), kResultsSchemaVersion));
  }
}

// The record's own fields; false when it cannot be read as a record. Metrics that are no
// number go to `unusable`.
bool check_fields(const nlohmann::json& j, std::set<std::string>& unusable, const Report& report) {
  if (!j.is_object()) {
    report("required_field", "not a JSON object");
    return false;
  }
  bool complete = true;
  for (const char* field : {"job_id", "case_id", "method", "status"}) {
    const auto it = j.find(field);
    if (it == j.end() || !it->is_string()) {
      report("required_field",
             fmt::format("\"{}\" is {}", field, it == j.end() ? "missing" : "not a string"));
      complete = false;
    }
  }
  const auto metrics = j.find("metrics");
  if (metrics == j.end() || !metrics->is_object()) {
    report("required_field",
           fmt::format("\"metrics\" is {}", metrics == j.end() ? "missing" : "not an object"));
    complete = false;
  } else {
    // The reader keeps numbers only: what else is there is reported here. A NaN or an
    // infinity is written as null.
    for (const auto& [name, value] : metrics->items()) {
      if (value.is_number())
        continue;
      unusable.insert(name);
      if (value.is_null())
        report("finite", name + " is null (not a number: NaN or infinity when written)");
      else
        report("finite", name + " is not a number: " + value.dump());
    }
  }
  // The method's settings: a built-in's, an object of flags, numbers and names; an external
  // method's, its command {"command": "...", optionally "vertex_tolerance_rel_diag": number}.
  if (const auto options = j.find("method_options"); options != j.end()) {
    if (!method_options_are_valid(*options)) {
      report("field_type",
             "\"method_options\" is neither an object of flags, numbers and names nor an "
             "external method's (a string \"command\", and a number "
             "\"vertex_tolerance_rel_diag\" if any): " +
                 options->dump());
      complete = false;
    }
  }
  if (const auto status = j.find("status"); status != j.end() && status->is_string()) {
    try {
      job_status_from_string(status->get<std::string>());
    } catch (const std::exception& e) {
      report("status", e.what());
      complete = false;
    }
  }
  return complete;
}

// Every check of a record's metrics and holes; `unusable`: metrics of the file that are no
// number (reported by check_fields, absent from the record).
void check_record(const JobRecord& record, const ValidationOptions& options,
                  std::set<std::string> unusable, const Report& report) {
  std::map<std::string, double> metrics;  // the finite ones: the others are reported once
  for (const auto& metric : record.metrics) {
    if (std::isfinite(metric.value)) {
      metrics[metric.name] = metric.value;
    } else {
      report("finite", named(metric.name, metric.value) + " is not a finite number");
      unusable.insert(metric.name);
    }
  }
  if (record.metrics.empty() &&
      (record.status == JobStatus::Ok || record.status == JobStatus::Partial)) {
    report("metrics_missing", fmt::format("status {} but no metrics (only a job that failed "
                                          "before its evaluation has none)",
                                          to_string(record.status)));
  }
  check_ranges(metrics, report);
  check_intervals(metrics, unusable, report);
  check_distance_order(metrics, options, report);
  check_chamfer(metrics, options, report);
  check_valid_repair(record, metrics, report);
  if (record.status == JobStatus::Ok) {
    for (const auto& hole : record.holes) {
      if (!hole.closed && !hole.arrow) {
        report("open_hole", fmt::format("status ok, but hole {} is open and has no guidance arrow",
                                        hole.hole_index));
      }
    }
  }
}

}  // namespace

std::vector<Violation> validate_record(const JobRecord& record, const ValidationOptions& options) {
  std::vector<Violation> violations;
  const std::string id = record.job.id();
  check_record(record, options, {}, [&](const char* check, std::string message) {
    violations.push_back({"", id, check, std::move(message)});
  });
  return violations;
}

ValidationReport validate_results_files(const std::vector<std::filesystem::path>& paths,
                                        const ValidationOptions& options) {
  ValidationReport result;
  std::map<std::string, std::string> first_use;  // job id -> "record N of FILE"
  for (const auto& path : paths) {
    const nlohmann::json document = read_results_document(path);
    const std::string file = path.string();
    check_context(document, [&](const char* check, std::string message) {
      result.violations.push_back({file, "", check, std::move(message)});
    });
    const auto& records = document["results"];
    for (std::size_t i = 0; i < records.size(); ++i) {
      ++result.records;
      const nlohmann::json& j = records[i];
      const auto written_id = j.is_object() ? j.find("job_id") : j.end();
      const bool has_id = j.is_object() && written_id != j.end() && written_id->is_string();
      const std::string label =
          has_id ? written_id->get<std::string>() : fmt::format("record {}", i);
      const Report report = [&](const char* check, std::string message) {
        result.violations.push_back({file, label, check, std::move(message)});
      };
      std::set<std::string> unusable;
      const bool complete = check_fields(j, unusable, report);
      if (has_id) {
        const auto [it, first] = first_use.emplace(label, fmt::format("record {} of {}", i, file));
        if (!first)
          report("duplicate_job_id", "the job id of " + it->second + " too");
      }
      // A record without its required fields cannot be read reliably: reported once.
      if (!complete)
        continue;
      JobRecord record;
      try {
        record = record_from_json(j);
      } catch (const std::exception& e) {
        report("field_type", std::string("the record cannot be read: ") + e.what());
        continue;
      }
      if (record.job.id() != label) {
        report("job_id_mismatch",
               "job_id differs from the id of the record's fields, " + record.job.id());
      }
      check_record(record, options, unusable, report);
    }
  }
  return result;
}

std::string format_violation(const Violation& violation) {
  std::string text;
  if (!violation.file.empty())
    text += violation.file + ": ";
  text += (violation.job_id.empty() ? std::string("context") : violation.job_id) + ": ";
  return text + violation.message + " [" + violation.check + "]";
}

std::string format_validation_summary(const ValidationReport& report) {
  return fmt::format("{} record{}, {} violation{}", report.records, report.records == 1 ? "" : "s",
                     report.violations.size(), report.violations.size() == 1 ? "" : "s");
}

}  // namespace holebench::harness
