#include "harness/run/suite.h"

#include "core/environment_path.h"
#include "core/errors.h"
#include "harness/results/json_fields.h"
#include "methods/external/predefined_external_methods.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <fstream>

#ifndef HOLEBENCH_SUITES_DIR
#define HOLEBENCH_SUITES_DIR "suites"
#endif

namespace holebench::harness {

std::filesystem::path default_suites_dir() {
  return environment_path_or("HOLEBENCH_SUITES_DIR", HOLEBENCH_SUITES_DIR);
}

namespace {

double non_negative(double value, const std::string& name) {
  if (value < 0.0)
    throw std::invalid_argument("field \"" + name + "\": " + fmt::format("{}", value) +
                                " is negative");
  return value;
}

MetricTolerance tolerance_from(const nlohmann::json& j, const std::string& name,
                               MetricTolerance base) {
  check_known_fields(j, name, {"direction", "relative", "absolute"});
  if (j.contains("direction")) {
    const auto direction = string_field(j, name, "direction", "");
    if (direction != "lower_is_better" && direction != "higher_is_better") {
      throw std::invalid_argument("field \"" + field_name(name, "direction") +
                                  "\" must be lower_is_better or higher_is_better");
    }
    base.lower_is_better = direction == "lower_is_better";
  }
  base.relative =
      non_negative(number_field(j, name, "relative", base.relative), field_name(name, "relative"));
  base.absolute =
      non_negative(number_field(j, name, "absolute", base.absolute), field_name(name, "absolute"));
  return base;
}

ExternalMethodSpec external_method_from(const nlohmann::json& j, const std::string& name_of_entry) {
  check_known_fields(j, name_of_entry, {"name", "command", "vertex_tolerance_rel_diag"});
  if (!j.contains("name"))
    throw std::invalid_argument("field \"" + field_name(name_of_entry, "name") + "\" is missing");
  const auto name = string_field(j, name_of_entry, "name", "");
  if (!j.contains("command")) {
    if (auto predefined = find_predefined_external_method(name))
      return *predefined;
    throw std::invalid_argument("external method '" + name +
                                "' has no \"command\" and is not a predefined one");
  }
  ExternalMethodSpec spec;
  spec.name = name;
  spec.command = string_field(j, name_of_entry, "command", "");
  spec.vertex_tolerance_rel_diag =
      non_negative(number_field(j, name_of_entry, "vertex_tolerance_rel_diag", 0.0),
                   field_name(name_of_entry, "vertex_tolerance_rel_diag"));
  check_external_method_name(spec.name);
  check_command_template(spec.command);
  return spec;
}

// A list the suite may not leave empty (an empty list would run nothing).
template <typename T>
const std::vector<T>& not_empty(const std::vector<T>& list, const char* name) {
  if (list.empty())
    throw std::invalid_argument("field \"" + std::string(name) + "\" is an empty list");
  return list;
}

void read_evaluation(const nlohmann::json& e, EvaluationOptions& o) {
  const std::string p = "evaluation";
  check_known_fields(
      e, p,
      {"hausdorff_error_bound_rel_diag", "mean_error_bound_rel_diag",
       "hole_mean_error_bound_rel_diag", "mean_relative_error_bound", "mean_query_budget",
       "hole_mean_query_budget", "self_intersections", "arrow_field_of_view_degrees"});
  const auto positive = [&](const char* key, double fallback) {
    const double value = number_field(e, p, key, fallback);
    if (!(value > 0.0))
      throw std::invalid_argument("field \"" + field_name(p, key) + "\" must be positive");
    return value;
  };
  o.hausdorff_error_bound_rel_diag =
      positive("hausdorff_error_bound_rel_diag", o.hausdorff_error_bound_rel_diag);
  o.mean_error_bound_rel_diag = positive("mean_error_bound_rel_diag", o.mean_error_bound_rel_diag);
  o.hole_mean_error_bound_rel_diag =
      positive("hole_mean_error_bound_rel_diag", o.hole_mean_error_bound_rel_diag);
  o.mean_relative_error_bound = positive("mean_relative_error_bound", o.mean_relative_error_bound);
  o.mean_query_budget = static_cast<decltype(o.mean_query_budget)>(integer_field(
      e, p, "mean_query_budget", static_cast<std::int64_t>(o.mean_query_budget), 1, 1LL << 40));
  o.hole_mean_query_budget = static_cast<decltype(o.hole_mean_query_budget)>(
      integer_field(e, p, "hole_mean_query_budget",
                    static_cast<std::int64_t>(o.hole_mean_query_budget), 1, 1LL << 40));
  o.self_intersections = bool_field(e, p, "self_intersections", o.self_intersections);
  o.arrow_field_of_view_degrees =
      positive("arrow_field_of_view_degrees", o.arrow_field_of_view_degrees);
}

void read_tolerances(const nlohmann::json& t, Tolerances& tolerances) {
  check_known_fields(t, "tolerances", {"default", "metrics", "ignored"});
  if (t.contains("default"))
    tolerances.default_tolerance = tolerance_from(t["default"], "tolerances.default", {});
  if (t.contains("metrics")) {
    if (!t["metrics"].is_object()) {
      throw std::invalid_argument("field \"tolerances.metrics\": expected an object, got " +
                                  quote_json(t["metrics"]));
    }
    for (const auto& [name, value] : t["metrics"].items()) {
      tolerances.metrics[name] =
          tolerance_from(value, "tolerances.metrics." + name, tolerances.default_tolerance);
    }
  }
  tolerances.ignored = string_list_field(t, "tolerances", "ignored", tolerances.ignored);
}

std::uint64_t memory_limit_from(const nlohmann::json& j) {
  const auto it = j.find("memory_limit");
  if (it == j.end())
    return kDefaultMemoryLimitBytes;
  if (it->is_string()) {
    try {
      return parse_memory_size(it->get<std::string>());
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("field \"memory_limit\": ") + e.what());
    }
  }
  return as_unsigned(*it, "memory_limit");  // bytes
}

Suite suite_from_json(const nlohmann::json& j, const std::filesystem::path& path) {
  check_known_fields(j, "",
                     {"name", "description", "cases", "methods", "external_methods", "users",
                      "noise_percent", "seeds", "include_cad", "meshes", "timeout_s",
                      "memory_limit", "method_repetitions", "evaluation", "tolerances"});
  Suite suite;
  suite.name = string_field(j, "", "name", path.stem().string());
  suite.description = string_field(j, "", "description", "");
  if (!j.contains("cases"))
    throw std::invalid_argument("field \"cases\" is missing");
  suite.case_patterns = not_empty(string_list_field(j, "", "cases", {}), "cases");
  suite.methods = string_list_field(j, "", "methods", {});  // empty: every built-in method
  if (j.contains("external_methods")) {
    if (!j["external_methods"].is_array())
      throw std::invalid_argument("field \"external_methods\": expected a list");
    for (std::size_t i = 0; i < j["external_methods"].size(); ++i) {
      suite.external_methods.push_back(external_method_from(
          j["external_methods"][i], "external_methods[" + std::to_string(i) + "]"));
    }
  }
  suite.users = not_empty(string_list_field(j, "", "users", suite.users), "users");
  suite.noise_levels =
      not_empty(number_list_field(j, "", "noise_percent", suite.noise_levels), "noise_percent");
  for (std::size_t i = 0; i < suite.noise_levels.size(); ++i)
    non_negative(suite.noise_levels[i], "noise_percent[" + std::to_string(i) + "]");
  suite.seeds = not_empty(unsigned_list_field(j, "", "seeds", suite.seeds), "seeds");
  suite.include_cad = bool_field(j, "", "include_cad", suite.include_cad);
  const auto meshes = string_list_field(j, "", "meshes", {});
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    if (meshes[i].empty())
      throw std::invalid_argument("field \"meshes[" + std::to_string(i) + "]\" is empty");
    suite.meshes.emplace_back(meshes[i]);
  }
  suite.timeout_seconds =
      non_negative(number_field(j, "", "timeout_s", suite.timeout_seconds), "timeout_s");
  suite.memory_limit_bytes = memory_limit_from(j);
  suite.method_repetitions = static_cast<int>(
      integer_field(j, "", "method_repetitions", suite.method_repetitions, 1, 1000));
  if (j.contains("evaluation"))
    read_evaluation(j["evaluation"], suite.evaluation);
  if (j.contains("tolerances"))
    read_tolerances(j["tolerances"], suite.tolerances);
  return suite;
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
    return suite_from_json(nlohmann::json::parse(in), path);
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

Suite ad_hoc_suite() {
  Suite suite;
  suite.name = "ad hoc";
  return suite;
}

Tolerances comparison_tolerances(const std::string& suite, const std::string& named_suite,
                                 bool* used_defaults) {
  if (used_defaults)
    *used_defaults = false;
  if (!suite.empty())
    return load_suite(suite).tolerances;
  const auto names = list_suites();
  if (std::find(names.begin(), names.end(), named_suite) != names.end())
    return load_suite(named_suite).tolerances;
  if (used_defaults)
    *used_defaults = true;
  return Tolerances{};
}

}  // namespace holebench::harness
