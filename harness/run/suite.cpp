#include "harness/run/suite.h"

#include "core/errors.h"
#include "methods/external/predefined_external_methods.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdlib>
#include <fstream>

#ifndef HOLEBENCH_SUITES_DIR
#define HOLEBENCH_SUITES_DIR "suites"
#endif

namespace holebench::harness {

namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

bool higher_is_better_metric(const std::string& metric) {
  return ends_with(metric, "_correct_fraction") || ends_with(metric, "_ok") ||
         metric.rfind("is_", 0) == 0 ||
         (metric.rfind("missing_edge_", 0) == 0 && ends_with(metric, "_fraction")) ||
         (metric.rfind("arrow_", 0) == 0 && ends_with(metric, "visible_fraction"));
}

bool informational_metric(const std::string& metric) {
  return metric == "input_faces_count" || metric == "new_faces_count" || metric == "arrows_count";
}

std::optional<MetricTolerance> Tolerances::find(const std::string& metric) const {
  if (std::find(ignored.begin(), ignored.end(), metric) != ignored.end())
    return std::nullopt;
  if (const auto it = metrics.find(metric); it != metrics.end())
    return it->second;
  if (informational_metric(metric))
    return std::nullopt;
  MetricTolerance tolerance = default_tolerance;
  tolerance.lower_is_better = !higher_is_better_metric(metric);
  return tolerance;
}

std::filesystem::path default_suites_dir() {
  if (const char* dir = std::getenv("HOLEBENCH_SUITES_DIR"); dir && *dir)
    return dir;
  return HOLEBENCH_SUITES_DIR;
}

namespace {

MetricTolerance tolerance_from(const nlohmann::json& j, MetricTolerance base) {
  if (j.contains("direction")) {
    const auto direction = j["direction"].get<std::string>();
    if (direction != "lower_is_better" && direction != "higher_is_better") {
      throw std::invalid_argument("direction must be lower_is_better or higher_is_better");
    }
    base.lower_is_better = direction == "lower_is_better";
  }
  base.relative = j.value("relative", base.relative);
  base.absolute = j.value("absolute", base.absolute);
  return base;
}

ExternalMethodSpec external_method_from(const nlohmann::json& j) {
  const auto name = j.at("name").get<std::string>();
  if (!j.contains("command")) {
    if (auto predefined = find_predefined_external_method(name))
      return *predefined;
    throw std::invalid_argument("external method '" + name +
                                "' has no \"command\" and is not a predefined one");
  }
  ExternalMethodSpec spec;
  spec.name = name;
  spec.command = j["command"].get<std::string>();
  spec.vertex_tolerance_rel_diag = j.value("vertex_tolerance_rel_diag", 0.0);
  check_external_method_name(spec.name);
  check_command_template(spec.command);
  return spec;
}

}  // namespace

Suite load_suite(const std::string& name_or_path, const std::filesystem::path& suites_dir) {
  std::filesystem::path path = name_or_path;
  if (path.extension() != ".json")
    path = suites_dir / (name_or_path + ".json");
  std::ifstream in(path);
  if (!in) {
    std::string known;
    for (const auto& name : list_suites(suites_dir))
      known += (known.empty() ? "" : ", ") + name;
    throw InvalidInputError("no suite '" + name_or_path + "' (" + path.string() +
                            " cannot be read); known suites: " + (known.empty() ? "none" : known));
  }
  try {
    const nlohmann::json j = nlohmann::json::parse(in);
    Suite suite;
    suite.name = j.value("name", path.stem().string());
    suite.description = j.value("description", "");
    suite.case_patterns = j.at("cases").get<std::vector<std::string>>();
    suite.methods = j.value("methods", std::vector<std::string>{});
    for (const auto& entry : j.value("external_methods", nlohmann::json::array()))
      suite.external_methods.push_back(external_method_from(entry));
    suite.users = j.value("users", suite.users);
    suite.noise_levels = j.value("noise_percent", suite.noise_levels);
    suite.seeds = j.value("seeds", suite.seeds);
    suite.include_cad = j.value("include_cad", suite.include_cad);
    suite.timeout_seconds = j.value("timeout_s", suite.timeout_seconds);
    suite.method_repetitions = j.value("method_repetitions", suite.method_repetitions);
    if (suite.method_repetitions < 1)
      throw std::invalid_argument("method_repetitions must be at least 1");
    if (j.contains("evaluation")) {
      const auto& e = j["evaluation"];
      auto& o = suite.evaluation;
      o.hausdorff_error_bound_rel_diag =
          e.value("hausdorff_error_bound_rel_diag", o.hausdorff_error_bound_rel_diag);
      o.mean_error_bound_rel_diag =
          e.value("mean_error_bound_rel_diag", o.mean_error_bound_rel_diag);
      o.hole_mean_error_bound_rel_diag =
          e.value("hole_mean_error_bound_rel_diag", o.hole_mean_error_bound_rel_diag);
      o.mean_relative_error_bound =
          e.value("mean_relative_error_bound", o.mean_relative_error_bound);
      o.mean_query_budget = e.value("mean_query_budget", o.mean_query_budget);
      o.hole_mean_query_budget = e.value("hole_mean_query_budget", o.hole_mean_query_budget);
      o.self_intersections = e.value("self_intersections", o.self_intersections);
      o.arrow_field_of_view_degrees =
          e.value("arrow_field_of_view_degrees", o.arrow_field_of_view_degrees);
    }
    if (j.contains("tolerances")) {
      const auto& t = j["tolerances"];
      if (t.contains("default"))
        suite.tolerances.default_tolerance = tolerance_from(t["default"], {});
      if (t.contains("metrics")) {
        for (const auto& [name, value] : t["metrics"].items()) {
          suite.tolerances.metrics[name] =
              tolerance_from(value, suite.tolerances.default_tolerance);
        }
      }
      suite.tolerances.ignored = t.value("ignored", suite.tolerances.ignored);
    }
    if (suite.case_patterns.empty())
      throw std::invalid_argument("\"cases\" is empty");
    return suite;
  } catch (const std::exception& e) {
    throw InvalidInputError(path.string() + ": " + e.what());
  }
}

std::vector<std::string> list_suites(const std::filesystem::path& suites_dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(suites_dir, error)) {
    if (entry.path().extension() == ".json")
      names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

}  // namespace holebench::harness
