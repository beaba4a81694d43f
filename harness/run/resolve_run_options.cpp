#include "harness/run/resolve_run_options.h"

#include "core/errors.h"

#include <fmt/format.h>

namespace holebench::harness {

Suite suite_of_run_flags(const RunFlags& flags, const std::filesystem::path& suites_dir) {
  if (!flags.suite.empty())
    return load_suite(flags.suite, suites_dir);
  if (flags.case_patterns.empty())
    return load_suite("default", suites_dir);
  Suite ad_hoc;
  ad_hoc.name = "ad hoc";
  return ad_hoc;
}

RunOptions resolve_run_options(const Suite& suite, const RunFlags& flags) {
  RunOptions options = run_options_from_suite(suite);
  options.out_dir = flags.out_dir;
  if (!flags.case_patterns.empty())
    options.case_patterns = flags.case_patterns;
  if (!flags.method_ids.empty())
    options.method_ids = flags.method_ids;
  options.external_methods.insert(options.external_methods.end(), flags.external_methods.begin(),
                                  flags.external_methods.end());
  if (flags.noise_levels)
    options.noise_levels = *flags.noise_levels;
  if (flags.seeds)
    options.seeds = *flags.seeds;
  if (flags.users)
    options.users = *flags.users;
  if (flags.hausdorff_error_bound_rel_diag)
    options.evaluation.hausdorff_error_bound_rel_diag = *flags.hausdorff_error_bound_rel_diag;

  if (!flags.user_meshes.empty()) {
    options.catalog.user_meshes = flags.user_meshes;
  } else {
    for (std::size_t i = 0; i < suite.meshes.size(); ++i) {
      if (!std::filesystem::exists(suite.meshes[i])) {
        throw InvalidInputError(fmt::format(
            "suite {}: field \"meshes[{}]\": {} does not exist (from {}; a relative path is "
            "relative to the current directory)",
            suite.name, i, suite.meshes[i].string(), std::filesystem::current_path().string()));
      }
    }
    options.catalog.user_meshes = suite.meshes;
  }
  options.catalog.prepare.tessellation = flags.brep_tessellation;
  if (flags.cad_data_dir)
    options.catalog.cad_data_dir = *flags.cad_data_dir;
  if (flags.no_cad)
    options.catalog.include_cad = false;

  options.snapshots = !flags.no_snapshots;
  options.viewer_meshes = !flags.no_viewer_meshes;
  options.runner.workers = flags.workers;
  if (flags.timeout_seconds)
    options.runner.timeout_seconds = *flags.timeout_seconds;
  options.runner.resume = flags.resume;
  if (flags.memory_limit_bytes)
    options.runner.memory_limit_bytes = *flags.memory_limit_bytes;
  if (flags.method_repetitions)
    options.method_repetitions = *flags.method_repetitions;
  if (flags.shard)
    options.shard = *flags.shard;
  return options;
}

}  // namespace holebench::harness
