#include "harness/results/record_json.h"

#include <stdexcept>

namespace holebench::harness {
namespace {

Point point_from(const nlohmann::json& j) {
  if (!j.is_array() || j.size() != 3)
    return Point(0, 0, 0);
  return Point(j[0].get<double>(), j[1].get<double>(), j[2].get<double>());
}

template <typename T>
T value_or(const nlohmann::json& j, const char* key, T fallback) {
  const auto it = j.find(key);
  if (it == j.end() || it->is_null())
    return fallback;
  return it->get<T>();
}

}  // namespace

nlohmann::ordered_json point_to_json(const Point& p) {
  return {p[0], p[1], p[2]};
}

JobStatus job_status_from_string(const std::string& name) {
  for (auto status :
       {JobStatus::Ok, JobStatus::Partial, JobStatus::MethodFailed, JobStatus::InvalidInput,
        JobStatus::Error, JobStatus::Crash, JobStatus::Timeout}) {
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
  RunContext context;
  context.schema_version = value_or(j, "schema_version", 0);
  context.code_version = value_or<std::string>(j, "code_version", "");
  context.build_type = value_or<std::string>(j, "build_type", "");
  context.host = value_or<std::string>(j, "host", "");
  context.created_utc = value_or<std::string>(j, "created_utc", "");
  context.suite = value_or<std::string>(j, "suite", "");
  context.shard = value_or<std::string>(j, "shard", "");
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

HoleLabels labels_from_json(const nlohmann::json& j) {
  HoleLabels labels;
  labels.k = value_or(j, "k", 0);
  labels.regions = value_or<std::vector<int>>(j, "regions", {});
  for (const auto& t : value_or<std::vector<std::string>>(j, "transitions", {})) {
    labels.transitions.push_back(t == "reflex" ? Convexity::Reflex : Convexity::Convex);
  }
  labels.orientation = value_or<std::string>(j, "orientation", "inner") == "outer"
                           ? Orientation::Outer
                           : Orientation::Inner;
  labels.orientation_known = value_or(j, "orientation_known", true);
  for (const auto& b : value_or<std::vector<std::string>>(j, "boundary_kinds", {})) {
    labels.boundary_kinds.push_back(b == "inner" ? BoundaryKind::Inner : BoundaryKind::Outer);
  }
  labels.linearly_dependent_faces = value_or(j, "linearly_dependent_faces", false);
  labels.size = value_or(j, "size", 0.0);
  labels.structure_size = value_or(j, "structure_size", 0.0);
  labels.expected_decision = value_or<std::string>(j, "expected_decision", "guide") == "close"
                                 ? Decision::CloseAutomatically
                                 : Decision::Guide;
  labels.known_weak_spot = value_or<std::string>(j, "known_weak_spot", "");
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
  nlohmann::ordered_json holes = nlohmann::ordered_json::array();
  for (const auto& hole : record.holes) {
    nlohmann::ordered_json h = {{"hole_index", hole.hole_index},
                                {"loop_size", hole.loop_size},
                                {"centroid", point_to_json(hole.centroid)},
                                {"closed", hole.closed},
                                {"new_faces", hole.new_faces},
                                {"note", hole.note},
                                {"fallback", hole.fallback}};
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
  JobRecord record;
  if (!j.contains("case_id") || !j.contains("method")) {
    throw std::invalid_argument("a record without case_id or method");
  }
  record.job.case_id = j["case_id"].get<std::string>();
  record.job.method_id = j["method"].get<std::string>();
  record.job.seed = value_or<std::uint64_t>(j, "seed", 0);
  if (j.contains("method_options") && j["method_options"].is_object() &&
      j["method_options"].contains("command")) {
    ExternalMethodSpec spec;
    spec.name = record.job.method_id;
    spec.command = value_or<std::string>(j["method_options"], "command", "");
    spec.vertex_tolerance_rel_diag =
        value_or(j["method_options"], "vertex_tolerance_rel_diag", 0.0);
    record.job.external = spec;
  }
  record.job.noise_percent = value_or(j, "noise_percent", 0.0);
  record.job.user = value_or<std::string>(j, "user", "no_user");
  record.case_family = value_or<std::string>(j, "case_family", "");
  record.case_kind = value_or<std::string>(j, "case_kind", "");
  record.user = record.job.user;
  record.user_interventions = value_or(j, "user_interventions", 0);
  if (j.contains("user_interventions_by_kind") && j["user_interventions_by_kind"].is_object()) {
    for (const auto& [kind, count] : j["user_interventions_by_kind"].items()) {
      if (count.is_number_integer())
        record.user_interventions_by_kind[kind] = count.get<int>();
    }
  }
  record.status = job_status_from_string(value_or<std::string>(j, "status", "ok"));
  record.message = value_or<std::string>(j, "message", "");
  if (j.contains("metrics") && j["metrics"].is_object()) {
    for (const auto& [name, value] : j["metrics"].items()) {
      if (value.is_number())
        record.metrics.push_back({name, value.get<double>()});
    }
  }
  if (j.contains("phases_s") && j["phases_s"].is_object()) {
    for (const auto& [name, value] : j["phases_s"].items()) {
      if (value.is_number())
        record.phases.push_back({name, value.get<double>()});
    }
  }
  record.method_seconds = value_or(j, "method_seconds", 0.0);
  if (j.contains("method_run_seconds") && j["method_run_seconds"].is_array()) {
    for (const auto& value : j["method_run_seconds"]) {
      if (value.is_number())
        record.method_run_seconds.push_back(value.get<double>());
    }
  } else {
    record.method_run_seconds.push_back(record.method_seconds);
  }
  if (j.contains("stages_s") && j["stages_s"].is_object()) {
    for (const auto& [name, value] : j["stages_s"].items()) {
      if (value.is_number())
        record.stages.push_back({name, value.get<double>()});
    }
  }
  if (j.contains("holes") && j["holes"].is_array()) {
    for (const auto& h : j["holes"]) {
      HoleRecord hole;
      hole.hole_index = value_or(h, "hole_index", 0);
      hole.loop_size = value_or<std::size_t>(h, "loop_size", 0);
      if (h.contains("centroid"))
        hole.centroid = point_from(h["centroid"]);
      hole.closed = value_or(h, "closed", false);
      hole.new_faces = value_or<std::size_t>(h, "new_faces", 0);
      hole.note = value_or<std::string>(h, "note", "");
      hole.fallback = value_or<std::string>(h, "fallback", "");
      if (h.contains("arrow") && h["arrow"].is_object()) {
        hole.arrow = GuidanceArrow{point_from(h["arrow"].value("position", nlohmann::json())),
                                   point_from(h["arrow"].value("direction", nlohmann::json()))};
      }
      if (h.contains("classification") && h["classification"].is_object()) {
        hole.classification = labels_from_json(h["classification"]);
      }
      record.holes.push_back(std::move(hole));
    }
  }
  record.snapshot = value_or<std::string>(j, "snapshot", "");
  return record;
}

}  // namespace holebench::harness
