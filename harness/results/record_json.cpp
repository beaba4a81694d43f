#include "harness/results/record_json.h"

#include "harness/results/json_fields.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <variant>

namespace holebench::harness {
namespace {

constexpr std::int64_t kIntMax = std::numeric_limits<int>::max();
constexpr std::int64_t kSizeMax = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kInt64Min = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kInt64Max = std::numeric_limits<std::int64_t>::max();

// [x, y, z]; anything else (written by an older version) is the origin.
Point point_from(const nlohmann::json& j, const std::string& name) {
  if (!j.is_array() || j.size() != 3)
    return Point(0, 0, 0);
  return Point(as_number(j[0], name + "[0]"), as_number(j[1], name + "[1]"),
               as_number(j[2], name + "[2]"));
}

// An object of numbers, {"name": seconds, ...}; other values are skipped (a NaN is written as
// null).
std::vector<PhaseTiming> timings_from(const nlohmann::json& j, const char* key) {
  std::vector<PhaseTiming> timings;
  const auto it = j.find(key);
  if (it == j.end() || !it->is_object())
    return timings;
  for (const auto& [name, value] : it->items()) {
    if (value.is_number())
      timings.push_back({name, value.get<double>()});
  }
  return timings;
}

// A number, or the fallback for null (a NaN or an infinity is written as null).
double number_or_null(const nlohmann::json& j, const std::string& parent, const char* key,
                      double fallback) {
  const auto it = j.find(key);
  if (it != j.end() && it->is_number_float() && !std::isfinite(it->get<double>()))
    return fallback;
  return number_field(j, parent, key, fallback);
}

nlohmann::ordered_json method_options_to_json(const MethodOptions& options) {
  nlohmann::ordered_json object = nlohmann::ordered_json::object();
  for (const auto& option : options.values())
    std::visit([&](const auto& value) { object[option.name] = value; }, option.value);
  return object;
}

// A built-in method's settings: an object of flags, integers, finite numbers and names.
MethodOptions method_options_from_json(const nlohmann::json& object, const std::string& name) {
  if (!object.is_object())
    throw std::invalid_argument("field \"" + name + "\": expected an object, got " +
                                quote_json(object));
  MethodOptions options;
  for (const auto& [key, value] : object.items()) {
    const std::string field = field_name(name, key);
    if (value.is_boolean())
      options.add(key, value.get<bool>());
    else if (value.is_number_integer())
      options.add(key, as_integer(value, field, kInt64Min, kInt64Max));
    else if (value.is_number_float())
      options.add(key, as_number(value, field));
    else
      options.add(key, as_string(value, field));
  }
  return options;
}

HoleRecord hole_from_json(const nlohmann::json& h, const std::string& name) {
  if (!h.is_object())
    throw std::invalid_argument("field \"" + name + "\": expected an object, got " + quote_json(h));
  HoleRecord hole;
  hole.hole_index = static_cast<int>(integer_field(h, name, "hole_index", 0, -kIntMax, kIntMax));
  hole.loop_size = static_cast<std::size_t>(integer_field(h, name, "loop_size", 0, 0, kSizeMax));
  if (h.contains("centroid"))
    hole.centroid = point_from(h["centroid"], field_name(name, "centroid"));
  hole.closed = bool_field(h, name, "closed", false);
  hole.new_faces = static_cast<std::size_t>(integer_field(h, name, "new_faces", 0, 0, kSizeMax));
  hole.note = string_field(h, name, "note", "");
  hole.fallback = string_field(h, name, "fallback", "");
  hole.defect = string_field(h, name, "defect", "");
  if (h.contains("arrow") && h["arrow"].is_object()) {
    const auto& arrow = h["arrow"];
    const std::string arrow_name = field_name(name, "arrow");
    hole.arrow = GuidanceArrow{
        point_from(arrow.value("position", nlohmann::json()), arrow_name + ".position"),
        point_from(arrow.value("direction", nlohmann::json()), arrow_name + ".direction")};
  }
  if (h.contains("classification") && h["classification"].is_object())
    hole.classification = labels_from_json(h["classification"], field_name(name, "classification"));
  return hole;
}

}  // namespace

nlohmann::ordered_json point_to_json(const Point& p) {
  return {p[0], p[1], p[2]};
}

JobStatus job_status_from_string(const std::string& name) {
  for (auto status :
       {JobStatus::Ok, JobStatus::Partial, JobStatus::MethodFailed, JobStatus::InvalidInput,
        JobStatus::Error, JobStatus::Crash, JobStatus::Timeout, JobStatus::OutOfMemory}) {
    if (name == to_string(status))
      return status;
  }
  throw std::invalid_argument("unknown job status '" + name + "'");
}

nlohmann::ordered_json context_to_json(const RunContext& context) {
  nlohmann::ordered_json j;
  j["schema_version"] = context.schema_version;
  j["code_version"] = context.code_version;
  j["build_type"] = context.build_type;
  j["host"] = context.host;
  j["created_utc"] = context.created_utc;
  j["suite"] = context.suite;
  if (!context.shard.empty())
    j["shard"] = context.shard;
  nlohmann::ordered_json libraries = nlohmann::ordered_json::object();
  for (const auto& [name, version] : context.libraries)
    libraries[name] = version;
  j["libraries"] = libraries;
  return j;
}

RunContext context_from_json(const nlohmann::json& j) {
  const std::string p = "context";
  if (!j.is_object())
    throw std::invalid_argument("field \"context\": expected an object, got " + quote_json(j));
  RunContext context;
  context.schema_version = static_cast<int>(
      integer_field(j, p, "schema_version", kResultsSchemaVersion, -kIntMax, kIntMax));
  if (context.schema_version != kResultsSchemaVersion) {
    throw std::invalid_argument(
        "field \"context.schema_version\": " + std::to_string(context.schema_version) +
        " is not the version this holebench reads (" + std::to_string(kResultsSchemaVersion) + ")");
  }
  context.code_version = string_field(j, p, "code_version", "");
  context.build_type = string_field(j, p, "build_type", "");
  context.host = string_field(j, p, "host", "");
  context.created_utc = string_field(j, p, "created_utc", "");
  context.suite = string_field(j, p, "suite", "");
  context.shard = string_field(j, p, "shard", "");
  if (j.contains("libraries") && j["libraries"].is_object()) {
    for (const auto& [name, version] : j["libraries"].items()) {
      context.libraries.emplace_back(
          name, version.is_string() ? version.get<std::string>() : version.dump());
    }
  }
  return context;
}

nlohmann::ordered_json labels_to_json(const HoleLabels& labels) {
  nlohmann::ordered_json j;
  j["k"] = labels.k;
  j["regions"] = labels.regions;
  auto& transitions = j["transitions"] = nlohmann::ordered_json::array();
  for (auto t : labels.transitions)
    transitions.push_back(to_string(t));
  j["orientation"] = to_string(labels.orientation);
  j["orientation_known"] = labels.orientation_known;
  auto& kinds = j["boundary_kinds"] = nlohmann::ordered_json::array();
  for (auto b : labels.boundary_kinds)
    kinds.push_back(to_string(b));
  j["linearly_dependent_faces"] = labels.linearly_dependent_faces;
  j["size"] = labels.size;
  j["structure_size"] = labels.structure_size;
  j["expected_decision"] = to_string(labels.expected_decision);
  j["known_weak_spot"] = labels.known_weak_spot;
  return j;
}

HoleLabels labels_from_json(const nlohmann::json& j, const std::string& p) {
  HoleLabels labels;
  labels.k = static_cast<int>(integer_field(j, p, "k", 0, -kIntMax, kIntMax));
  if (j.contains("regions") && !j["regions"].is_null()) {
    const auto& regions = j["regions"];
    if (!regions.is_array())
      throw std::invalid_argument("field \"" + field_name(p, "regions") + "\": expected a list");
    for (std::size_t i = 0; i < regions.size(); ++i) {
      labels.regions.push_back(static_cast<int>(
          as_integer(regions[i], field_name(p, "regions") + "[" + std::to_string(i) + "]", -kIntMax,
                     kIntMax)));
    }
  }
  for (const auto& t : string_list_field(j, p, "transitions", {}))
    labels.transitions.push_back(t == "reflex" ? Convexity::Reflex : Convexity::Convex);
  labels.orientation = string_field(j, p, "orientation", "inner") == "outer" ? Orientation::Outer
                                                                             : Orientation::Inner;
  labels.orientation_known = bool_field(j, p, "orientation_known", true);
  for (const auto& b : string_list_field(j, p, "boundary_kinds", {}))
    labels.boundary_kinds.push_back(b == "inner" ? BoundaryKind::Inner : BoundaryKind::Outer);
  labels.linearly_dependent_faces = bool_field(j, p, "linearly_dependent_faces", false);
  labels.size = number_or_null(j, p, "size", 0.0);
  labels.structure_size = number_or_null(j, p, "structure_size", 0.0);
  labels.expected_decision = string_field(j, p, "expected_decision", "guide") == "close"
                                 ? Decision::CloseAutomatically
                                 : Decision::Guide;
  labels.known_weak_spot = string_field(j, p, "known_weak_spot", "");
  return labels;
}

nlohmann::ordered_json record_to_json(const JobRecord& record) {
  nlohmann::ordered_json j;
  j["job_id"] = record.job.id();
  j["case_id"] = record.job.case_id;
  j["method"] = record.job.method_id;
  j["seed"] = record.job.seed;
  if (record.job.external) {
    nlohmann::ordered_json options = {{"command", record.job.external->command}};
    if (record.job.external->vertex_tolerance_rel_diag > 0.0)
      options["vertex_tolerance_rel_diag"] = record.job.external->vertex_tolerance_rel_diag;
    j["method_options"] = options;
  } else if (!record.job.method_options.empty()) {
    j["method_options"] = method_options_to_json(record.job.method_options);
  }
  j["case_family"] = record.case_family;
  j["case_kind"] = record.case_kind;
  j["noise_percent"] = record.job.noise_percent;
  j["user"] = record.user;
  j["user_interventions"] = record.user_interventions;
  if (!record.user_interventions_by_kind.empty()) {
    nlohmann::ordered_json by_kind = nlohmann::ordered_json::object();
    for (const auto& [kind, count] : record.user_interventions_by_kind)
      by_kind[kind] = count;
    j["user_interventions_by_kind"] = by_kind;
  }
  j["status"] = to_string(record.status);
  j["message"] = record.message;
  nlohmann::ordered_json metrics = nlohmann::ordered_json::object();
  for (const auto& metric : record.metrics)
    metrics[metric.name] = metric.value;
  j["metrics"] = metrics;
  nlohmann::ordered_json phases = nlohmann::ordered_json::object();
  for (const auto& phase : record.phases)
    phases[phase.phase] = phase.seconds;
  j["phases_s"] = phases;
  j["method_seconds"] = record.method_seconds;
  if (record.method_run_seconds.size() > 1)
    j["method_run_seconds"] = record.method_run_seconds;
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  for (const auto& stage : record.stages)
    stages[stage.phase] = stage.seconds;
  j["stages_s"] = stages;
  if (!record.evaluation_phases.empty()) {
    nlohmann::ordered_json evaluation_phases = nlohmann::ordered_json::object();
    for (const auto& phase : record.evaluation_phases)
      evaluation_phases[phase.phase] = phase.seconds;
    j["evaluation_phases_s"] = evaluation_phases;
  }
  nlohmann::ordered_json holes = nlohmann::ordered_json::array();
  for (const auto& hole : record.holes) {
    nlohmann::ordered_json h = {{"hole_index", hole.hole_index},
                                {"loop_size", hole.loop_size},
                                {"centroid", point_to_json(hole.centroid)},
                                {"closed", hole.closed},
                                {"new_faces", hole.new_faces},
                                {"note", hole.note},
                                {"fallback", hole.fallback}};
    if (!hole.defect.empty())
      h["defect"] = hole.defect;
    if (hole.arrow) {
      h["arrow"] = {{"position", point_to_json(hole.arrow->position)},
                    {"direction", point_to_json(hole.arrow->direction)}};
    }
    if (hole.classification)
      h["classification"] = labels_to_json(*hole.classification);
    holes.push_back(h);
  }
  j["holes"] = holes;
  j["snapshot"] = record.snapshot;
  return j;
}

JobRecord record_from_json(const nlohmann::json& j) {
  if (!j.is_object())
    throw std::invalid_argument("a record is not a JSON object: " + quote_json(j));
  JobRecord record;
  for (const char* required : {"case_id", "method"}) {
    if (!j.contains(required) || j[required].is_null())
      throw std::invalid_argument(std::string("field \"") + required + "\" is missing");
  }
  record.job.case_id = string_field(j, "", "case_id", "");
  record.job.method_id = string_field(j, "", "method", "");
  record.job.seed = unsigned_field(j, "", "seed", 0);
  if (j.contains("method_options") && j["method_options"].is_object() &&
      j["method_options"].contains("command")) {
    ExternalMethodSpec spec;
    spec.name = record.job.method_id;
    spec.command = string_field(j["method_options"], "method_options", "command", "");
    spec.vertex_tolerance_rel_diag =
        number_field(j["method_options"], "method_options", "vertex_tolerance_rel_diag", 0.0);
    record.job.external = spec;
  } else if (j.contains("method_options")) {
    record.job.method_options = method_options_from_json(j["method_options"], "method_options");
  }
  record.job.noise_percent = number_field(j, "", "noise_percent", 0.0);
  record.job.user = string_field(j, "", "user", "no_user");
  record.case_family = string_field(j, "", "case_family", "");
  record.case_kind = string_field(j, "", "case_kind", "");
  record.user = record.job.user;
  record.user_interventions =
      static_cast<int>(integer_field(j, "", "user_interventions", 0, 0, kIntMax));
  if (j.contains("user_interventions_by_kind") && j["user_interventions_by_kind"].is_object()) {
    for (const auto& [kind, count] : j["user_interventions_by_kind"].items()) {
      if (count.is_number_integer() && count.get<std::int64_t>() >= 0 &&
          count.get<std::int64_t>() <= kIntMax)
        record.user_interventions_by_kind[kind] = count.get<int>();
    }
  }
  try {
    record.status = job_status_from_string(string_field(j, "", "status", "ok"));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("field \"status\": ") + e.what());
  }
  record.message = string_field(j, "", "message", "");
  // Metrics: numbers are kept; a NaN or an infinity is written as null and left out
  // (holebench validate reports it).
  for (const auto& metric : timings_from(j, "metrics"))
    record.metrics.push_back({metric.phase, metric.seconds});
  record.phases = timings_from(j, "phases_s");
  record.method_seconds = number_or_null(j, "", "method_seconds", 0.0);
  if (j.contains("method_run_seconds") && j["method_run_seconds"].is_array()) {
    for (const auto& value : j["method_run_seconds"]) {
      if (value.is_number())
        record.method_run_seconds.push_back(value.get<double>());
    }
  } else {
    record.method_run_seconds.push_back(record.method_seconds);
  }
  record.stages = timings_from(j, "stages_s");
  record.evaluation_phases = timings_from(j, "evaluation_phases_s");
  if (j.contains("holes") && j["holes"].is_array()) {
    for (std::size_t i = 0; i < j["holes"].size(); ++i)
      record.holes.push_back(hole_from_json(j["holes"][i], "holes[" + std::to_string(i) + "]"));
  }
  record.snapshot = string_field(j, "", "snapshot", "");
  return record;
}

std::string record_to_json_line(const JobRecord& record) {
  return record_to_json(record).dump();
}

JobRecord record_from_json_text(const std::string& json_text) {
  return record_from_json(nlohmann::json::parse(json_text));
}

}  // namespace holebench::harness
