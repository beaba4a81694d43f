// The JSON form of the results' context block and of one job record, both ways. Writers emit
// numbers as numbers; readers ignore fields they do not know and take defaults for missing
// ones (results written by an older holebench still read).
#pragma once

#include "harness/results/record.h"
#include "harness/results/run_context.h"

#include <nlohmann/json.hpp>

#include <string>

namespace holebench::harness {

nlohmann::ordered_json context_to_json(const RunContext& context);
/// Throws std::invalid_argument for a schema_version other than kResultsSchemaVersion.
RunContext context_from_json(const nlohmann::json& j);

nlohmann::ordered_json record_to_json(const JobRecord& record);
/// Throws std::invalid_argument naming the field for a record without case_id or method, with
/// an unknown status, or with a field of the wrong type or out of its type's range (a string
/// for a number, a negative count, an integer too large for its type).
JobRecord record_from_json(const nlohmann::json& j);

/// The JSON text of one record (one line, as the runner appends it to records.jsonl).
std::string record_to_json_line(const JobRecord& record);
/// One record from its JSON text (as record_to_json_line writes it); throws as
/// record_from_json does, or nlohmann::json::parse_error for text that is not JSON.
JobRecord record_from_json_text(const std::string& json_text);

nlohmann::ordered_json point_to_json(const Point& p);  ///< [x, y, z]

nlohmann::ordered_json labels_to_json(const HoleLabels& labels);
/// `parent`: the field's name in error messages.
HoleLabels labels_from_json(const nlohmann::json& j, const std::string& parent = "classification");

/// A status from its name ("ok", "partial", ...); throws std::invalid_argument otherwise.
JobStatus job_status_from_string(const std::string& name);

}  // namespace holebench::harness
