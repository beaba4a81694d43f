// holebench slurm submit | status | resubmit: a suite as a Slurm job array, one task a shard.
#include "harness/cli/common_flags.h"
#include "harness/cli/subcommands.h"
#include "harness/cluster/shard_status.h"
#include "harness/cluster/slurm_submit.h"
#include "harness/run/shard.h"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace holebench::harness::cli {

namespace {

struct SlurmFlags {
  SlurmSubmitOptions submit;
  std::string submit_only;
  bool submit_no_snapshots = false;
  int submit_workers = 0;
  double submit_timeout = -1.0;
  std::filesystem::path status_dir;
  SlurmResubmitOptions resubmit;
  std::string resubmit_only;
};

std::vector<std::size_t> shard_indices(const std::string& list) {
  if (list.empty())
    return {};
  return parse_shard_list(list, std::numeric_limits<std::size_t>::max());
}

// "shard-1, shard-3"
std::string shard_names(const std::vector<std::size_t>& indices) {
  std::string names;
  for (auto index : indices)
    names += (names.empty() ? "" : ", ") + shard_folder_name(index);
  return names;
}

int submit(SlurmFlags& flags) {
  auto& submit_options = flags.submit;
  ShardRunFlags run_flags;
  run_flags.no_snapshots = flags.submit_no_snapshots;
  run_flags.workers = flags.submit_workers;
  if (flags.submit_timeout >= 0.0)
    run_flags.timeout_seconds = flags.submit_timeout;
  submit_options.run_arguments = shard_run_arguments(run_flags);
  submit_options.only = shard_indices(flags.submit_only);
  const auto result = submit_shards(submit_options);
  fmt::print("{}", format_submission(result, submit_options.out_dir));
  return 0;
}

int status(const SlurmFlags& flags) {
  const auto report = shard_status(flags.status_dir);
  fmt::print("{}", format_shard_status(report));
  return report.all_complete() ? 0 : 1;
}

int resubmit(SlurmFlags& flags) {
  auto& resubmit_options = flags.resubmit;
  resubmit_options.only = shard_indices(flags.resubmit_only);
  const auto result = resubmit_shards(resubmit_options);
  if (!result.warning.empty())
    fmt::print(stderr, "holebench slurm resubmit: {}\n", result.warning);
  if (!result.still_queued.empty()) {
    fmt::print(
        "Still in Slurm's queue, left alone: {} (--even-if-queued to resubmit them "
        "anyway)\n",
        shard_names(result.still_queued));
  }
  if (result.shards.empty() && !result.still_queued.empty())
    return 0;
  if (result.shards.empty()) {
    fmt::print(
        "Every shard is complete: nothing to resubmit. Merge with: holebench merge "
        "--shards {}\n",
        resubmit_options.dir.string());
    return 0;
  }
  fmt::print("Resubmitting {}\n", shard_names(result.shards));
  fmt::print("{}", format_submission(result, resubmit_options.dir));
  return 0;
}

}  // namespace

Subcommand add_slurm_command(CLI::App& app) {
  auto flags = std::make_shared<SlurmFlags>();
  auto* slurm = app.add_subcommand(
      "slurm",
      "Run a suite on a Slurm cluster: a job array with one task per shard (holebench run "
      "--shard I/N); see docs/cluster.md");
  slurm->require_subcommand(1);
  auto& submit_options = flags->submit;
  auto* submit_command = slurm->add_subcommand(
      "submit",
      "Write DIR/shards.json and the sbatch script DIR/slurm/shards.sbatch (--array=0-(N-1), "
      "task I runs `holebench run --suite NAME --shard I/N --out DIR/shard-I --resume`) and "
      "submit it. sbatch options go after --, e.g. -- --partition=short --time=02:00:00");
  submit_command->add_option("--suite", submit_options.suite, "Suite name or path")->required();
  submit_command
      ->add_option("--shards", submit_options.shard_count,
                   "Number of shards N (array tasks 0 to N-1)")
      ->required()
      ->check(CLI::Range(std::size_t{1}, std::size_t{100000}));
  submit_command->add_option("--out", submit_options.out_dir, "The sharded run's folder")
      ->required();
  submit_command->add_option("--workers,-j", flags->submit_workers,
                             "Jobs at once in each task (default: the CPUs Slurm gives the "
                             "task, $SLURM_CPUS_PER_TASK)");
  submit_command
      ->add_option("--timeout", flags->submit_timeout,
                   "Seconds a job may take before it is stopped (default: the suite's)")
      ->check(CLI::NonNegativeNumber);
  submit_command->add_flag("--no-snapshots", flags->submit_no_snapshots,
                           "Do not render a PNG per job");
  submit_command->add_option("--holebench", submit_options.holebench,
                             "The holebench binary the tasks run, on a file system the nodes "
                             "share (default: this one)");
  submit_command
      ->add_option("--only", flags->submit_only,
                   "Submit only these shards (array indices), e.g. 1,3 or 0-2,7")
      ->check(parsed_by(shard_indices, "LIST"));
  submit_command->add_flag("--dry-run", submit_options.dry_run,
                           "Write the manifest and the script and print the sbatch command, "
                           "without submitting");
  submit_command->add_option("sbatch_options", submit_options.sbatch_options,
                             "Options for sbatch, after --");

  auto* status_command = slurm->add_subcommand(
      "status",
      "Each shard of a sharded run: complete, incomplete (running, or its task failed) or "
      "missing, by name; exit code 1 unless all are complete");
  status_command->add_option("--out", flags->status_dir, "The sharded run's folder")
      ->required()
      ->check(CLI::ExistingDirectory);

  auto& resubmit_options = flags->resubmit;
  auto* resubmit_command = slurm->add_subcommand(
      "resubmit",
      "Submit again the shards that are not complete (or --only those), as array indices of the "
      "same script; each keeps the jobs it had finished. sbatch options go after -- (default: "
      "those of the submission)");
  resubmit_command->add_option("--out", resubmit_options.dir, "The sharded run's folder")
      ->required()
      ->check(CLI::ExistingDirectory);
  resubmit_command
      ->add_option("--only", flags->resubmit_only, "Resubmit only these shards, e.g. 1,3")
      ->check(parsed_by(shard_indices, "LIST"));
  resubmit_command->add_flag("--even-if-queued", resubmit_options.even_if_queued,
                             "Also resubmit shards whose task squeue still lists (pending or "
                             "running); by default they are left alone");
  resubmit_command->add_flag("--dry-run", resubmit_options.dry_run,
                             "Print the sbatch command without submitting");
  resubmit_command->add_option("sbatch_options", resubmit_options.sbatch_options,
                               "Options for sbatch, after --");

  return {slurm, [flags, submit_command, status_command, resubmit_command] {
            if (submit_command->parsed())
              return submit(*flags);
            if (status_command->parsed())
              return status(*flags);
            if (resubmit_command->parsed())
              return resubmit(*flags);
            return 0;
          }};
}

}  // namespace holebench::harness::cli
