// holebench merge: results files joined by job id, or the shards of a sharded run.
#include "harness/cli/subcommands.h"
#include "harness/cluster/shard_merge.h"
#include "harness/cluster/shard_status.h"
#include "harness/results/merge_results.h"

#include <cstdio>
#include <filesystem>
#include <memory>
#include <vector>

namespace holebench::harness::cli {

namespace {

struct MergeFlags {
  std::vector<std::filesystem::path> inputs;
  std::filesystem::path out;
  std::filesystem::path shards_dir;
  bool allow_incomplete = false;
};

int merge_sharded_run(const MergeFlags& flags) {
  ShardMergeOptions options;
  options.dir = flags.shards_dir;
  options.out_dir = flags.out;
  options.allow_incomplete = flags.allow_incomplete;
  const auto result = merge_shards(options);
  if (!result.written) {
    std::fprintf(stderr, "holebench: not merged: some shards are not complete\n%s",
                 format_shard_status(result.status).c_str());
    return 1;
  }
  if (!result.missing_jobs.empty()) {
    std::fprintf(stderr, "holebench: %zu of %zu jobs missing (incomplete shards):\n%s",
                 result.missing_jobs.size(), result.status.manifest.job_ids.size(),
                 format_shard_status(result.status).c_str());
  }
  std::fprintf(stderr, "%zu records from %zu shards into %s\n", result.merged.records.size(),
               result.status.shards.size(), result.results_json.c_str());
  return 0;
}

int merge_files(const MergeFlags& flags) {
  if (flags.inputs.empty() || flags.out.empty()) {
    std::fprintf(stderr, "holebench merge: give results.json files and --out, or --shards DIR\n");
    return 2;
  }
  const auto result = merge_results_files(flags.inputs, flags.out);
  std::fprintf(stderr, "%zu records from %zu files into %s\n", result.merged.records.size(),
               flags.inputs.size(), result.results_json.c_str());
  return 0;
}

}  // namespace

Subcommand add_merge_command(CLI::App& app) {
  auto flags = std::make_shared<MergeFlags>();
  auto* merge = app.add_subcommand(
      "merge",
      "Join results files (matched by job id; later files win), or with --shards the shards of "
      "a sharded run into one results file equal to a single-machine run's, up to timings");
  auto* inputs_option =
      merge->add_option("inputs", flags->inputs, "results.json files")->check(CLI::ExistingFile);
  auto* shards_option =
      merge
          ->add_option("--shards", flags->shards_dir,
                       "A sharded run's folder (holebench slurm submit --out DIR): merges its "
                       "shard-I/ results in the suite's order; exit code 1, naming the shards, "
                       "if some are missing or incomplete")
          ->check(CLI::ExistingDirectory)
          ->excludes(inputs_option);
  inputs_option->excludes(shards_option);
  merge->add_option("--out", flags->out,
                    "Output folder for the merged results.json and results.csv (with --shards, "
                    "default: the sharded run's folder); locked while merging, like run's --out");
  merge->add_flag("--allow-incomplete", flags->allow_incomplete,
                  "With --shards: merge the records there are even if shards are not complete");
  return {merge, [flags] {
            return flags->shards_dir.empty() ? merge_files(*flags) : merge_sharded_run(*flags);
          }};
}

}  // namespace holebench::harness::cli
