// `holebench slurm submit` and `slurm resubmit`: a suite run as a Slurm job array, one task
// per shard (harness/run/shard.h). Slurm does the scheduling; each task is a plain
// `holebench run --shard I/N --resume` into DIR/shard-I, so a resubmitted shard keeps the
// jobs it had finished. Writes the manifest (harness/cluster/shard_manifest.h) and the sbatch
// script, then calls sbatch; a dry run writes both and prints the sbatch command instead.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace holebench::harness {

struct SlurmSubmitOptions {
  std::string suite;  ///< suite name (suites/<name>.json) or path to a suite file
  std::size_t shard_count = 0;
  std::filesystem::path out_dir;
  /// The binary each task runs; empty: this process's own (/proc/self/exe). Must be
  /// reachable under the same path on the compute nodes (a shared file system).
  std::filesystem::path holebench;
  /// Added to each task's `holebench run`, e.g. {"--no-snapshots", "--timeout", "600"}.
  /// Without "--workers", a task runs as many jobs at once as Slurm gave it CPUs.
  std::vector<std::string> run_arguments;
  std::vector<std::string> sbatch_options;  ///< passed to sbatch, e.g. "--partition=short"
  std::vector<std::size_t> only;            ///< the shards to submit; empty: all
  bool dry_run = false;                     ///< write the files, do not call sbatch
  std::string sbatch = "sbatch";            ///< the sbatch command (tests use a stand-in)
};

/// The flags of `holebench slurm submit` that each task passes on to its `holebench run`.
struct ShardRunFlags {
  bool no_snapshots = false;              ///< --no-snapshots
  int workers = 0;                        ///< --workers N; 0: not given (Slurm's CPUs)
  std::optional<double> timeout_seconds;  ///< --timeout S
};

/// `flags` as arguments of `holebench run` (SlurmSubmitOptions::run_arguments): "--no-snapshots",
/// "--workers" N, "--timeout" S (S in its shortest form: "600", "2.5"), each only if given.
std::vector<std::string> shard_run_arguments(const ShardRunFlags& flags);

struct SlurmResubmitOptions {
  std::filesystem::path dir;  ///< a sharded run's folder (DIR/shards.json)
  /// The shards to resubmit; empty: every shard that is not complete.
  std::vector<std::size_t> only;
  /// Passed to sbatch; empty: those of the first submission (from the manifest).
  std::vector<std::string> sbatch_options;
  bool dry_run = false;
  std::string sbatch = "sbatch";
  /// Asked which array tasks of this run's submissions are still pending or running: those
  /// are left alone (a second task on the same shard folder would write beside the first)
  /// unless `even_if_queued`. If it cannot be run, every unfinished shard is resubmitted, as
  /// the result's warning says.
  std::string squeue = "squeue";
  bool even_if_queued = false;
};

struct SlurmSubmitResult {
  std::filesystem::path script;
  std::filesystem::path manifest;
  std::vector<std::size_t> shards;          ///< the submitted array indices; empty: nothing to do
  std::string array;                        ///< the --array value, e.g. "0-3" or "1,3"
  std::vector<std::string> sbatch_command;  ///< what was (or, in a dry run, would be) run
  std::string slurm_job_id;                 ///< from sbatch --parsable; empty in a dry run
  bool submitted = false;
  /// Resubmission: unfinished shards left out because their task is still in Slurm's queue.
  std::vector<std::size_t> still_queued;
  std::string warning;  ///< resubmission: why the queue could not be checked, if it could not
};

/// The array indices of `job_ids`' tasks in `squeue --noheader --array --format=%i` output
/// ("4242_3" lines; a line "4242" or "4242_[0-3]" is a whole pending array, given by
/// `arrays`, the --array value of each submission by job id).
std::vector<std::size_t> queued_array_tasks(const std::string& squeue_output,
                                            const std::map<std::string, std::string>& arrays,
                                            std::size_t shard_count);

/// The job array script: one task per shard, each `holebench run --suite FILE --shard
/// $SLURM_ARRAY_TASK_ID/N --out DIR/shard-$SLURM_ARRAY_TASK_ID --resume ...`, with its
/// output in DIR/slurm/shard-%a.log. All paths absolute.
std::string sbatch_script(const std::filesystem::path& suite_file, const std::string& suite_name,
                          std::size_t shard_count, const std::filesystem::path& out_dir,
                          const std::filesystem::path& holebench,
                          const std::vector<std::string>& run_arguments);

/// Plans the suite, writes DIR/shards.json and DIR/slurm/shards.sbatch, and submits the array
/// (or `only` its listed shards). Throws InvalidInputError for bad options (no shards, an
/// unknown suite, a DIR holding another sharded run) and std::runtime_error when sbatch
/// fails or cannot be found.
SlurmSubmitResult submit_shards(const SlurmSubmitOptions& options);

/// Submits again, with the script of the first submission, the shards of `options.dir` that
/// are not complete (harness/cluster/shard_status.h), or those listed in `only`.
SlurmSubmitResult resubmit_shards(const SlurmResubmitOptions& options);

/// What `holebench slurm submit` / `resubmit` prints about a submission of the run in `dir`:
/// the Slurm job id and array (or, in a dry run, the sbatch command to submit it), then the
/// script, the manifest, the logs and the status and merge commands, with absolute paths.
std::string format_submission(const SlurmSubmitResult& result, const std::filesystem::path& dir);

/// `text` quoted for a POSIX shell ('...'), unquoted when it needs no quoting.
std::string shell_quote(const std::string& text);

}  // namespace holebench::harness
