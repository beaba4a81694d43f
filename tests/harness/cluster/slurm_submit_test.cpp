// `holebench slurm submit` / `resubmit` without Slurm: the script and the manifest written by
// a dry run, and the sbatch command line given to a stand-in sbatch that records it.
// (tests/slurm/slurm_cluster_test.sh runs the real thing.)
#include "harness/cluster/slurm_submit.h"

#include "harness/cluster/shard_manifest.h"
#include "harness/results/record_json.h"
#include "harness/results/results_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace holebench::harness {
namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_slurm_submit_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// A stand-in sbatch: appends its arguments to `log` and answers like sbatch --parsable.
std::string fake_sbatch(const std::filesystem::path& dir, const std::filesystem::path& log) {
  const auto path = dir / "fake_sbatch";
  std::ofstream(path) << "#!/bin/sh\necho \"$*\" >> '" << log.string()
                      << "'\necho '4242;cluster'\n";
  std::filesystem::permissions(path, std::filesystem::perms::owner_all);
  return path.string();
}

SlurmSubmitOptions smoke_options(const std::filesystem::path& dir) {
  SlurmSubmitOptions options;
  options.suite = "smoke";
  options.shard_count = 4;
  options.out_dir = dir / "run";
  options.holebench = "/opt/holebench/bin/holebench";
  options.run_arguments = {"--no-snapshots"};
  options.sbatch_options = {"--partition=short", "--time=01:00:00"};
  return options;
}

TEST(SlurmSubmit, DryRunWritesTheArrayScriptAndTheManifest) {
  const auto dir = fresh_dir("dry_run");
  auto options = smoke_options(dir);
  options.dry_run = true;
  const auto result = submit_shards(options);
  EXPECT_FALSE(result.submitted);
  EXPECT_EQ(result.array, "0-3");
  const auto script = read_text(result.script);
  const auto run = (dir / "run").string();
  EXPECT_NE(script.find("#SBATCH --array=0-3\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --output=" + run + "/slurm/shard-%a.log"), std::string::npos);
  EXPECT_NE(script.find("exec /opt/holebench/bin/holebench run --suite "), std::string::npos);
  EXPECT_NE(script.find("smoke.json --shard \"${shard}/4\" --out " + run +
                        "/\"shard-${shard}\" --resume --no-snapshots --workers "
                        "\"${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-1}}\""),
            std::string::npos)
      << script;
  EXPECT_NE(script.find("shard=\"${SLURM_ARRAY_TASK_ID:?"), std::string::npos);
  EXPECT_EQ(result.sbatch_command,
            (std::vector<std::string>{"sbatch", "--parsable", "--array=0-3", "--partition=short",
                                      "--time=01:00:00", result.script.string()}));

  const auto manifest = read_shard_manifest(dir / "run");
  EXPECT_EQ(manifest.suite, "smoke");
  EXPECT_EQ(manifest.shard_count, 4u);
  EXPECT_GT(manifest.job_ids.size(), 100u);
  EXPECT_TRUE(manifest.submissions.empty());
}

TEST(SlurmSubmit, SubmitsAndResubmitsOnlyTheUnfinishedShards) {
  const auto dir = fresh_dir("submit");
  const auto log = dir / "sbatch.log";
  auto options = smoke_options(dir);
  options.sbatch = fake_sbatch(dir, log);
  const auto result = submit_shards(options);
  EXPECT_TRUE(result.submitted);
  EXPECT_EQ(result.slurm_job_id, "4242");
  EXPECT_EQ(read_text(log), "--parsable --array=0-3 --partition=short --time=01:00:00 " +
                                result.script.string() + "\n");

  // Shard 1 has finished (every record and results.json); 0, 2, 3 have not.
  const auto manifest = read_shard_manifest(dir / "run");
  ASSERT_EQ(manifest.submissions.size(), 1u);
  EXPECT_EQ(manifest.submissions[0].array, "0-3");
  const auto shard1 = shard_dir(dir / "run", 1);
  std::filesystem::create_directories(shard1);
  {
    std::ofstream records(shard1 / "records.jsonl");
    for (const auto& id : shard_job_ids(manifest, 1)) {
      // The job back from its id "case|method|user|noise|seed".
      std::vector<std::string> fields;
      std::stringstream parts(id);
      for (std::string field; std::getline(parts, field, '|');)
        fields.push_back(field);
      ASSERT_EQ(fields.size(), 5u) << id;
      JobRecord record;
      record.job = {fields[0], fields[1], std::stod(fields[3]), std::stoull(fields[4]), fields[2]};
      ASSERT_EQ(record.job.id(), id);
      records << record_to_json_line(record) << '\n';
    }
  }
  std::ofstream(shard1 / "results.json") << "{\"results\": []}\n";

  SlurmResubmitOptions resubmit;
  resubmit.dir = dir / "run";
  resubmit.sbatch = options.sbatch;
  resubmit.squeue = "true";  // an empty queue
  const auto again = resubmit_shards(resubmit);
  EXPECT_EQ(again.array, "0,2-3");
  resubmit.only = {2};
  resubmit.sbatch_options = {"--time=04:00:00"};
  EXPECT_EQ(resubmit_shards(resubmit).array, "2");
  EXPECT_EQ(read_text(log), "--parsable --array=0-3 --partition=short --time=01:00:00 " +
                                result.script.string() +
                                "\n--parsable --array=0,2-3 --partition=short --time=01:00:00 " +
                                result.script.string() + "\n--parsable --array=2 --time=04:00:00 " +
                                result.script.string() + "\n");
  EXPECT_EQ(read_shard_manifest(dir / "run").submissions.size(), 3u);
}

// squeue's lines name array tasks "JOB_INDEX", or a pending array's remaining tasks
// "JOB_[0,2-3]"; other jobs are ignored.
TEST(SlurmSubmit, QueuedArrayTasksFromSqueue) {
  const std::map<std::string, std::string> arrays = {{"4242", "0-3"}, {"4300", "1,3"}};
  EXPECT_EQ(queued_array_tasks("4242_0\n  4242_3\n999_1\n", arrays, 4),
            (std::vector<std::size_t>{0, 3}));
  EXPECT_EQ(queued_array_tasks("4300_[1,3%2]\n", arrays, 4), (std::vector<std::size_t>{1, 3}));
  EXPECT_EQ(queued_array_tasks("4242\n", arrays, 4), (std::vector<std::size_t>{0, 1, 2, 3}));
  EXPECT_TRUE(queued_array_tasks("", arrays, 4).empty());
  EXPECT_TRUE(queued_array_tasks("4242_9\n", arrays, 4).empty());  // not a shard of this run
}

// A shard whose task is still pending or running is not resubmitted beside it.
TEST(SlurmSubmit, ResubmitLeavesShardsStillInTheQueue) {
  const auto dir = fresh_dir("queued");
  const auto log = dir / "sbatch.log";
  auto options = smoke_options(dir);
  options.sbatch = fake_sbatch(dir, log);
  submit_shards(options);
  const auto squeue = dir / "fake_squeue";
  std::ofstream(squeue) << "#!/bin/sh\necho '4242_1'\necho '4242_3'\necho '17_2'\n";
  std::filesystem::permissions(squeue, std::filesystem::perms::owner_all);
  SlurmResubmitOptions resubmit;
  resubmit.dir = dir / "run";
  resubmit.sbatch = options.sbatch;
  resubmit.squeue = squeue.string();
  const auto result = resubmit_shards(resubmit);
  EXPECT_EQ(result.array, "0,2");
  EXPECT_EQ(result.still_queued, (std::vector<std::size_t>{1, 3}));
  EXPECT_TRUE(result.warning.empty());
  resubmit.even_if_queued = true;
  EXPECT_EQ(resubmit_shards(resubmit).array, "0-3");
  // Without squeue: every unfinished shard, and a warning saying why.
  resubmit.even_if_queued = false;
  resubmit.squeue = (dir / "no_such_squeue").string();
  const auto blind = resubmit_shards(resubmit);
  EXPECT_EQ(blind.array, "0-3");
  EXPECT_NE(blind.warning.find("could not ask Slurm"), std::string::npos) << blind.warning;
}

TEST(SlurmSubmit, RefusesAFolderHoldingAnotherRun) {
  const auto dir = fresh_dir("other_run");
  auto options = smoke_options(dir);
  options.dry_run = true;
  submit_shards(options);
  options.shard_count = 5;
  EXPECT_THROW(submit_shards(options), std::invalid_argument);
  options.shard_count = 0;
  EXPECT_THROW(submit_shards(options), std::invalid_argument);
}

TEST(SlurmSubmit, AMissingSbatchSaysSo) {
  const auto dir = fresh_dir("no_sbatch");
  auto options = smoke_options(dir);
  options.sbatch = (dir / "no_such_sbatch").string();
  try {
    submit_shards(options);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("--dry-run"), std::string::npos) << e.what();
  }
}

TEST(SlurmSubmit, ShellQuoting) {
  EXPECT_EQ(shell_quote("/a/b-c_d.json"), "/a/b-c_d.json");
  EXPECT_EQ(shell_quote("a b"), "'a b'");
  EXPECT_EQ(shell_quote("it's"), "'it'\\''s'");
  EXPECT_EQ(shell_quote(""), "''");
}

// The flags `slurm submit` passes on to each task's `holebench run`: only those given, in a
// fixed order; a timeout in its shortest form.
TEST(SlurmSubmit, ShardRunArgumentsAreTheFlagsGiven) {
  EXPECT_TRUE(shard_run_arguments({}).empty());
  ShardRunFlags flags;
  flags.no_snapshots = true;
  flags.workers = 8;
  flags.timeout_seconds = 2.5;
  EXPECT_EQ(shard_run_arguments(flags),
            (std::vector<std::string>{"--no-snapshots", "--workers", "8", "--timeout", "2.5"}));
  ShardRunFlags timeout_only;
  timeout_only.timeout_seconds = 600.0;
  EXPECT_EQ(shard_run_arguments(timeout_only), (std::vector<std::string>{"--timeout", "600"}));
  timeout_only.timeout_seconds = 0.0;  // 0: no limit, passed on like any other value
  EXPECT_EQ(shard_run_arguments(timeout_only), (std::vector<std::string>{"--timeout", "0"}));
}

// What submit prints: the job id and array when submitted, the quoted sbatch command in a dry
// run, then where everything is.
TEST(SlurmSubmit, FormatSubmission) {
  SlurmSubmitResult result;
  result.script = "/runs/r/slurm/shards.sbatch";
  result.manifest = "/runs/r/shards.json";
  result.sbatch_command = {"sbatch", "--array=0-3", "--comment=a b", "/runs/r/slurm/shards.sbatch"};
  const std::string where =
      "  script:   /runs/r/slurm/shards.sbatch\n  manifest: /runs/r/shards.json\n"
      "  logs:     /runs/r/slurm/shard-<I>.log\n"
      "  status:   holebench slurm status --out /runs/r\n"
      "  merge:    holebench merge --shards /runs/r\n";
  EXPECT_EQ(format_submission(result, "/runs/r"),
            "Dry run: not submitted. To submit:\n"
            "  sbatch --array=0-3 '--comment=a b' /runs/r/slurm/shards.sbatch\n" +
                where);
  result.submitted = true;
  result.slurm_job_id = "4242";
  result.array = "0-3";
  EXPECT_EQ(format_submission(result, "/runs/r"), "Submitted Slurm job 4242: array 0-3\n" + where);
}

}  // namespace
}  // namespace holebench::harness
