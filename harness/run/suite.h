// Named suites: which cases, methods, users, noise levels and seeds a run covers, with
// which options, and the tolerances `holebench compare` judges regressions by. Suites are
// JSON files in suites/ (suites/<name>.json), reviewed like code.
#pragma once

#include "generators/case_catalog.h"
#include "harness/results/tolerances.h"
#include "harness/run/memory_limit.h"
#include "methods/external/external_method_spec.h"
#include "metrics/evaluation.h"
#include "metrics/metric_names.h"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct Suite {
  std::string name;
  std::string description;
  std::vector<std::string> case_patterns;
  std::vector<std::string> methods;  ///< empty: every built-in method
  /// "external_methods": programs run as methods beside `methods`, each
  /// {"name": ..., "command": ..., optionally "vertex_tolerance_rel_diag": ...}, or
  /// {"name": ...} alone for a predefined one (meshlab_close_holes).
  std::vector<ExternalMethodSpec> external_methods;
  std::vector<std::string> users{"no_user"};
  std::vector<double> noise_levels{0.0};
  std::vector<std::uint64_t> seeds{0};
  bool include_cad = true;
  /// "meshes": the user's model files or folders (meshes, STEP, IGES, BREP), read as
  /// `--mesh` is; a relative path is relative to the current directory. Their cases are
  /// file/<stem>/...; `--mesh` replaces them.
  std::vector<std::filesystem::path> meshes;
  double timeout_seconds = 300.0;  ///< per job
  /// "memory_limit": each job's address space ("4G", "512MiB", bytes; "0": none); default
  /// 4 GiB (harness/run/memory_limit.h).
  std::uint64_t memory_limit_bytes = kDefaultMemoryLimitBytes;
  int method_repetitions = 1;  ///< runs of the method per job; its time is their median
  EvaluationOptions evaluation;
  Tolerances tolerances;
};

/// The suite of a run that names no suite, only cases: the built-in defaults of `Suite`
/// (every built-in method, no_user, noise 0, seed 0, CAD models included, 300 s, 4 GiB) named
/// "ad hoc", with no case patterns (the run's cases then default to default_case_patterns()).
Suite ad_hoc_suite();

/// The folder holding the suite files: $HOLEBENCH_SUITES_DIR if set, else the source tree's
/// suites/ (compiled in).
std::filesystem::path default_suites_dir();

/// Reads suite `name_or_path`: a path to a .json file, or a name looked up as
/// <suites_dir>/<name>.json. Throws InvalidInputError with the file and the field on error:
/// a field of the wrong type, an unknown field (a typo would silently change the run), an
/// empty list of cases, users, noise levels or seeds, a negative noise level, timeout or
/// tolerance.
Suite load_suite(const std::string& name_or_path,
                 const std::filesystem::path& suites_dir = default_suites_dir());

/// The names of the suites in `suites_dir`, sorted.
std::vector<std::string> list_suites(
    const std::filesystem::path& suites_dir = default_suites_dir());

/// The tolerances that judge a comparison (harness/results/compare.h): those of the suite
/// `suite` when it is not empty (a name or a path; load_suite throws for an unknown one), else
/// those of `named_suite` (the suite a results file's context names) when it is a known suite,
/// else the built-in defaults, and then `*used_defaults` is set (when given).
Tolerances comparison_tolerances(const std::string& suite, const std::string& named_suite,
                                 bool* used_defaults = nullptr);

}  // namespace holebench::harness
