#include "harness/run/resolve_run_options.h"

#include "core/errors.h"

#include <fmt/format.h>

namespace holebench::harness {

namespace {

// The suite's meshes, each of which must exist (a relative path is relative to the current
// directory).
void check_suite_meshes_exist(const Suite& suite) {
  for (std::size_t i = 0; i < suite.meshes.size(); ++i) {
    if (!std::filesystem::exists(suite.meshes[i])) {
      throw InvalidInputError(fmt::format(
          "suite {}: field \"meshes[{}]\": {} does not exist (from {}; a relative path is "
          "relative to the current directory)",
          suite.name, i, suite.meshes[i].string(), std::filesystem::current_path().string()));
    }
  }
}

// The suite with every flag given overriding its field.
Suite suite_with_flags(Suite suite, const RunFlags& flags) {
  if (!flags.case_patterns.empty())
    suite.case_patterns = flags.case_patterns;
  if (!flags.method_ids.empty())
    suite.methods = flags.method_ids;
  suite.external_methods.insert(suite.external_methods.end(), flags.external_methods.begin(),
                                flags.external_methods.end());
  if (flags.noise_levels)
    suite.noise_levels = *flags.noise_levels;
  if (flags.seeds)
    suite.seeds = *flags.seeds;
  if (flags.users)
    suite.users = *flags.users;
  if (flags.hausdorff_error_bound_rel_diag)
    suite.evaluation.hausdorff_error_bound_rel_diag = *flags.hausdorff_error_bound_rel_diag;
  if (!flags.user_meshes.empty())
    suite.meshes = flags.user_meshes;
  else
    check_suite_meshes_exist(suite);
  if (flags.no_cad)
    suite.include_cad = false;
  if (flags.timeout_seconds)
    suite.timeout_seconds = *flags.timeout_seconds;
  if (flags.memory_limit_bytes)
    suite.memory_limit_bytes = *flags.memory_limit_bytes;
  if (flags.method_repetitions)
    suite.method_repetitions = *flags.method_repetitions;
  return suite;
}

}  // namespace

Suite suite_of_run_flags(const RunFlags& flags, const std::filesystem::path& suites_dir) {
  if (!flags.suite.empty())
    return load_suite(flags.suite, suites_dir);
  if (flags.case_patterns.empty())
    return load_suite("default", suites_dir);
  return ad_hoc_suite();
}

RunOptions resolve_run_options(const Suite& suite, const RunFlags& flags) {
  RunOptions options;
  options.suite = suite_with_flags(suite, flags);
  options.out_dir = flags.out_dir;
  options.prepare.tessellation = flags.brep_tessellation;
  if (flags.cad_data_dir)
    options.cad_data_dir = *flags.cad_data_dir;
  options.snapshots = !flags.no_snapshots;
  options.viewer_meshes = !flags.no_viewer_meshes;
  options.layers = flags.layers;
  options.repaired_meshes = flags.repaired_meshes;
  options.workers = flags.workers;
  options.resume = flags.resume;
  if (flags.shard)
    options.shard = *flags.shard;
  return options;
}

}  // namespace holebench::harness
