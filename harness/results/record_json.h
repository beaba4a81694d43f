// The JSON form of the results' context block and of one job record, both ways. Writers emit
// numbers as numbers; readers ignore fields they do not know and take defaults for missing
// ones (results written by an older holebench still read).
#pragma once

#include "harness/results/results_file.h"
#include "harness/run/job.h"

#include <nlohmann/json.hpp>

namespace holebench::harness {

nlohmann::ordered_json context_to_json(const RunContext& context);
RunContext context_from_json(const nlohmann::json& j);

nlohmann::ordered_json record_to_json(const JobRecord& record);
/// Throws std::invalid_argument for a record without a job id or with an unknown status.
JobRecord record_from_json(const nlohmann::json& j);

nlohmann::ordered_json point_to_json(const Point& p);  ///< [x, y, z]

nlohmann::ordered_json labels_to_json(const HoleLabels& labels);
HoleLabels labels_from_json(const nlohmann::json& j);

/// A status from its name ("ok", "partial", ...); throws std::invalid_argument otherwise.
JobStatus job_status_from_string(const std::string& name);

}  // namespace holebench::harness
