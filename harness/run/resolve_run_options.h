// How `holebench run` combines a suite with the flags given on the command line: the suite
// gives the defaults, each flag given overrides its field, and flags a suite does not know
// (the output folder, workers, snapshots, ...) are taken as given.
#pragma once

#include "core/occt/brep_mesh.h"
#include "harness/run/run_jobs.h"
#include "harness/run/shard.h"
#include "harness/run/suite.h"
#include "methods/external/external_method_spec.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

/// The flags of `holebench run`, parsed; an empty list or an unset optional is a flag not
/// given, which leaves the suite's value.
struct RunFlags {
  std::filesystem::path out_dir;                         ///< --out
  std::string suite;                                     ///< --suite, a name or path
  std::vector<std::string> case_patterns;                ///< --case
  std::vector<std::string> method_ids;                   ///< --method
  std::vector<ExternalMethodSpec> external_methods;      ///< --external, after the suite's own
  std::optional<std::vector<double>> noise_levels;       ///< --noise
  std::optional<std::vector<std::uint64_t>> seeds;       ///< --seed
  std::optional<std::vector<std::string>> users;         ///< --user
  std::optional<double> hausdorff_error_bound_rel_diag;  ///< --hausdorff-error-bound
  std::vector<std::filesystem::path> user_meshes;        ///< --mesh
  occt::TessellationOptions brep_tessellation;           ///< --brep-deflection (always applied)
  std::optional<std::filesystem::path> cad_data_dir;     ///< --cad-dir
  bool no_cad = false;                                   ///< --no-cad
  bool no_snapshots = false;                             ///< --no-snapshots
  bool no_viewer_meshes = false;                         ///< --no-viewer-meshes
  bool layers = false;                                   ///< --layers
  bool repaired_meshes = false;                          ///< --repaired-meshes
  int workers = 0;                                       ///< --workers; 0: the number of cores
  std::optional<double> timeout_seconds;                 ///< --timeout
  bool resume = false;                                   ///< --resume
  std::optional<std::uint64_t> memory_limit_bytes;       ///< --memory-limit
  std::optional<int> method_repetitions;                 ///< --method-repetitions
  std::optional<ShardSpec> shard;                        ///< --shard
};

/// The suite a run starts from: --suite if given (loaded from `suites_dir` by name, or a
/// path); the default suite when no --case is given either; otherwise (only --case) an ad hoc
/// run: a `Suite` with the built-in defaults (every built-in method, no_user, noise 0, seed 0,
/// CAD models included, 300 s, 4 GiB) named "ad hoc". Throws as load_suite() does.
Suite suite_of_run_flags(const RunFlags& flags,
                         const std::filesystem::path& suites_dir = default_suites_dir());

/// The run options of `suite` with every flag given in `flags` overriding the suite's field: cases,
/// methods, noise levels, seeds, users, the Hausdorff error bound, the timeout, the memory limit,
/// the method repetitions; --no-cad leaves the CAD models out even where the suite includes them;
/// --external methods run after the suite's. The suite's meshes unless --mesh is given (a missing
/// one is an InvalidInputError naming the suite and the field). The rest (output folder, B-Rep
/// tessellation, snapshots, workers, resume, shard) comes from `flags` alone.
RunOptions resolve_run_options(const Suite& suite, const RunFlags& flags);

}  // namespace holebench::harness
