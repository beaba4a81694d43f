#include "harness/cluster/slurm_submit.h"

#include "core/errors.h"
#include "generators/case_catalog.h"
#include "harness/cluster/shard_manifest.h"
#include "harness/cluster/shard_status.h"
#include "harness/run/run_jobs.h"
#include "harness/run/shard.h"
#include "harness/run/suite.h"

#include <fmt/format.h>

#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <ctime>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>

extern char** environ;

namespace holebench::harness {

std::string shell_quote(const std::string& text) {
  const bool plain = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::strchr("/._-+=:,@%", c);
  });
  if (plain)
    return text;
  std::string quoted = "'";
  for (char c : text) {
    if (c == '\'')
      quoted += "'\\''";
    else
      quoted += c;
  }
  return quoted + "'";
}

namespace {

std::filesystem::path absolute_path(const std::filesystem::path& path) {
  return std::filesystem::absolute(path).lexically_normal();
}

std::string utc_now() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char stamp[32];
  std::strftime(stamp, sizeof(stamp), "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return stamp;
}

std::filesystem::path this_executable() {
  std::error_code error;
  const auto path = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error)
    throw std::runtime_error("cannot find this program's path (/proc/self/exe); pass --holebench");
  return path;
}

// The suite's file: a path as given, or suites/<name>.json.
std::filesystem::path suite_file_of(const std::string& suite) {
  const std::filesystem::path path = suite;
  if (path.extension() == ".json")
    return absolute_path(path);
  return absolute_path(default_suites_dir() / (suite + ".json"));
}

std::vector<std::string> plan_job_ids(const Suite& suite) {
  RunOptions run_options;
  run_options.suite = suite;
  const generators::CaseCatalog catalog(run_catalog_options(run_options));
  std::vector<std::string> ids;
  for (const auto& job : plan_jobs(run_options, catalog))
    ids.push_back(job.id());
  return ids;
}

// Runs `command` (stdout captured, stderr passed through) and returns its stdout.
std::string run_and_capture(const std::vector<std::string>& command) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, fds[1], STDOUT_FILENO);
  posix_spawn_file_actions_addclose(&actions, fds[0]);
  std::vector<char*> argv;
  for (const auto& arg : command)
    argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  const int spawned = ::posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(fds[1]);
  if (spawned != 0) {
    ::close(fds[0]);
    throw std::runtime_error(fmt::format(
        "cannot run {}: {} (is Slurm installed here? --dry-run writes the script without "
        "submitting it)",
        command[0], std::strerror(spawned)));
  }
  std::string output;
  char buffer[4096];
  for (ssize_t n; (n = ::read(fds[0], buffer, sizeof(buffer))) != 0;) {
    if (n < 0 && errno == EINTR)
      continue;
    if (n < 0)
      break;
    output.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::string line;
    for (const auto& arg : command)
      line += (line.empty() ? "" : " ") + shell_quote(arg);
    throw std::runtime_error(fmt::format("{} failed (exit code {}; its message is above): {}",
                                         command[0], WIFEXITED(status) ? WEXITSTATUS(status) : -1,
                                         line));
  }
  return output;
}

// sbatch --parsable prints "<job id>" or "<job id>;<cluster>".
std::string job_id_of_parsable(const std::string& output) {
  std::string id = output.substr(0, output.find_first_of(";\n"));
  id.erase(0, id.find_first_not_of(" \t"));
  return id;
}

// Writes the manifest's submission and calls sbatch (unless a dry run).
SlurmSubmitResult submit_array(const std::filesystem::path& dir, ShardManifest manifest,
                               const std::vector<std::size_t>& shards,
                               const std::vector<std::string>& sbatch_options, bool dry_run,
                               const std::string& sbatch) {
  SlurmSubmitResult result;
  result.script = slurm_script_path(dir);
  result.manifest = shard_manifest_path(dir);
  result.shards = shards;
  result.array = shard_list_to_array_spec(shards);
  result.sbatch_command = {sbatch, "--parsable", "--array=" + result.array};
  result.sbatch_command.insert(result.sbatch_command.end(), sbatch_options.begin(),
                               sbatch_options.end());
  result.sbatch_command.push_back(result.script.string());
  if (!dry_run) {
    result.slurm_job_id = job_id_of_parsable(run_and_capture(result.sbatch_command));
    result.submitted = true;
    manifest.submissions.push_back({result.slurm_job_id, result.array, utc_now()});
    write_shard_manifest(dir, manifest);
  }
  return result;
}

void check_same_run(const ShardManifest& existing, const ShardManifest& wanted,
                    const std::filesystem::path& dir) {
  std::string difference;
  if (existing.suite != wanted.suite)
    difference = fmt::format("suite {} (not {})", existing.suite, wanted.suite);
  else if (existing.shard_count != wanted.shard_count)
    difference = fmt::format("{} shards (not {})", existing.shard_count, wanted.shard_count);
  else if (existing.job_ids != wanted.job_ids)
    difference = "a different list of jobs (the suite or the code changed since)";
  if (!difference.empty()) {
    throw InvalidInputError(fmt::format(
        "{} already holds a sharded run with {}: use another --out, or `holebench slurm "
        "resubmit --out {}` to finish that run",
        dir.string(), difference, dir.string()));
  }
}

}  // namespace

std::string sbatch_script(const std::filesystem::path& suite_file, const std::string& suite_name,
                          std::size_t shard_count, const std::filesystem::path& out_dir,
                          const std::filesystem::path& holebench,
                          const std::vector<std::string>& run_arguments) {
  const bool workers_given =
      std::any_of(run_arguments.begin(), run_arguments.end(), [](const std::string& arg) {
        return arg == "--workers" || arg == "-j" || arg.rfind("--workers=", 0) == 0;
      });
  std::string extra;
  for (const auto& arg : run_arguments)
    extra += " " + shell_quote(arg);
  if (!workers_given)
    extra += " --workers \"${SLURM_CPUS_PER_TASK:-${SLURM_CPUS_ON_NODE:-1}}\"";
  const std::string last = std::to_string(shard_count - 1);
  std::string script;
  script += "#!/bin/bash\n";
  script += fmt::format("# holebench: suite {} in {} shards, one per task of this job array.\n",
                        suite_name, shard_count);
  script += "# Written by `holebench slurm submit`, which also submits it. Task I runs shard I/N\n";
  script += "# into DIR/shard-I with --resume: a resubmitted task keeps the jobs already done.\n";
  script +=
      fmt::format("#   status:   holebench slurm status --out {}\n", shell_quote(out_dir.string()));
  script += fmt::format("#   resubmit: holebench slurm resubmit --out {}\n",
                        shell_quote(out_dir.string()));
  script +=
      fmt::format("#   merge:    holebench merge --shards {}\n", shell_quote(out_dir.string()));
  script += fmt::format("#SBATCH --job-name=holebench-{}\n", suite_name);
  script += fmt::format("#SBATCH --array=0-{}\n", last);
  script += fmt::format("#SBATCH --output={}\n", slurm_log_pattern(out_dir).string());
  script += "#SBATCH --open-mode=append\n";
  script += "set -euo pipefail\n";
  script += fmt::format(
      "shard=\"${{SLURM_ARRAY_TASK_ID:?submit this script with sbatch --array=0-{}}}\"\n", last);
  script += "echo \"holebench shard ${shard}/" + std::to_string(shard_count) +
            " on $(hostname), Slurm job ${SLURM_JOB_ID:-?}, $(date -u +%FT%TZ)\"\n";
  script += fmt::format(
      "exec {} run --suite {} --shard \"${{shard}}/{}\" --out {}/\"shard-${{shard}}\" "
      "--resume{}\n",
      shell_quote(holebench.string()), shell_quote(suite_file.string()), shard_count,
      shell_quote(out_dir.string()), extra);
  return script;
}

SlurmSubmitResult submit_shards(const SlurmSubmitOptions& options) {
  if (options.shard_count == 0)
    throw InvalidInputError("--shards must be at least 1");
  if (options.out_dir.empty())
    throw InvalidInputError("--out is required");
  for (auto index : options.only) {
    if (index >= options.shard_count) {
      throw InvalidInputError(fmt::format("--only: shard {} does not exist (shards 0 to {})", index,
                                          options.shard_count - 1));
    }
  }
  const auto dir = absolute_path(options.out_dir);
  const auto suite_file = suite_file_of(options.suite);
  const Suite suite = load_suite(suite_file.string());

  ShardManifest manifest;
  manifest.suite = suite.name;
  manifest.suite_file = suite_file;
  manifest.shard_count = options.shard_count;
  manifest.job_ids = plan_job_ids(suite);
  manifest.holebench =
      absolute_path(options.holebench.empty() ? this_executable() : options.holebench);
  manifest.run_arguments = options.run_arguments;
  manifest.sbatch_options = options.sbatch_options;
  if (std::filesystem::exists(shard_manifest_path(dir))) {
    const auto existing = read_shard_manifest(dir);
    check_same_run(existing, manifest, dir);
    manifest.submissions = existing.submissions;
  }
  if (manifest.job_ids.size() < options.shard_count) {
    std::fprintf(stderr, "holebench: note: %zu jobs in %zu shards: some shards have no job\n",
                 manifest.job_ids.size(), options.shard_count);
  }

  std::filesystem::create_directories(slurm_script_path(dir).parent_path());
  write_shard_manifest(dir, manifest);
  const auto script_path = slurm_script_path(dir);
  {
    std::ofstream out(script_path, std::ios::binary);
    out << sbatch_script(manifest.suite_file, manifest.suite, manifest.shard_count, dir,
                         manifest.holebench, manifest.run_arguments);
    if (!out)
      throw std::runtime_error("cannot write " + script_path.string());
  }
  std::filesystem::permissions(script_path, std::filesystem::perms::owner_exec,
                               std::filesystem::perm_options::add);

  std::vector<std::size_t> shards = options.only;
  std::sort(shards.begin(), shards.end());
  shards.erase(std::unique(shards.begin(), shards.end()), shards.end());
  if (shards.empty()) {
    for (std::size_t i = 0; i < options.shard_count; ++i)
      shards.push_back(i);
  }
  return submit_array(dir, manifest, shards, options.sbatch_options, options.dry_run,
                      options.sbatch);
}

std::vector<std::size_t> queued_array_tasks(const std::string& squeue_output,
                                            const std::map<std::string, std::string>& arrays,
                                            std::size_t shard_count) {
  std::set<std::size_t> queued;
  std::istringstream lines(squeue_output);
  for (std::string line; std::getline(lines, line);) {
    line.erase(0, line.find_first_not_of(" \t"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    const auto underscore = line.find('_');
    const auto it = arrays.find(line.substr(0, underscore));
    if (it == arrays.end())
      continue;  // another job
    std::string tasks = underscore == std::string::npos ? it->second : line.substr(underscore + 1);
    if (!tasks.empty() && tasks.front() == '[') {
      // A pending array's remaining tasks, "[0,2-3]" or "[2-3%4]" (a throttle).
      tasks = tasks.substr(1, tasks.find_first_of("]%") - 1);
    }
    try {
      for (auto index : parse_shard_list(tasks, shard_count))
        queued.insert(index);
    } catch (const std::invalid_argument&) {
      // Not ours to read: leave it.
    }
  }
  return {queued.begin(), queued.end()};
}

SlurmSubmitResult resubmit_shards(const SlurmResubmitOptions& options) {
  const auto dir = absolute_path(options.dir);
  const auto status = shard_status(dir);
  if (!std::filesystem::exists(slurm_script_path(dir))) {
    throw InvalidInputError(slurm_script_path(dir).string() +
                            " not found: submit the run first (holebench slurm submit)");
  }
  std::vector<std::size_t> shards = options.only;
  for (auto index : shards) {
    if (index >= status.manifest.shard_count) {
      throw InvalidInputError(fmt::format("--only: shard {} does not exist (shards 0 to {})", index,
                                          status.manifest.shard_count - 1));
    }
  }
  if (shards.empty())
    shards = status.unfinished();
  // Tasks still pending or running keep their shards.
  std::vector<std::size_t> still_queued;
  std::string warning;
  std::map<std::string, std::string> arrays;
  for (const auto& submission : status.manifest.submissions) {
    if (!submission.slurm_job_id.empty())
      arrays[submission.slurm_job_id] = submission.array;
  }
  if (!options.even_if_queued && !arrays.empty() && !shards.empty()) {
    try {
      const auto queued = queued_array_tasks(
          run_and_capture({options.squeue, "--noheader", "--array", "--format=%i"}), arrays,
          status.manifest.shard_count);
      std::vector<std::size_t> kept;
      for (auto index : shards) {
        if (std::binary_search(queued.begin(), queued.end(), index))
          still_queued.push_back(index);
        else
          kept.push_back(index);
      }
      shards = kept;
    } catch (const std::exception& e) {
      warning = fmt::format(
          "could not ask Slurm which shards are still queued ({}): resubmitting every "
          "unfinished shard",
          e.what());
    }
  }
  if (shards.empty()) {
    SlurmSubmitResult nothing;
    nothing.script = slurm_script_path(dir);
    nothing.manifest = shard_manifest_path(dir);
    nothing.still_queued = still_queued;
    nothing.warning = warning;
    return nothing;
  }
  std::sort(shards.begin(), shards.end());
  shards.erase(std::unique(shards.begin(), shards.end()), shards.end());
  const auto& sbatch_options =
      options.sbatch_options.empty() ? status.manifest.sbatch_options : options.sbatch_options;
  SlurmSubmitResult result =
      submit_array(dir, status.manifest, shards, sbatch_options, options.dry_run, options.sbatch);
  result.still_queued = still_queued;
  result.warning = warning;
  return result;
}

std::vector<std::string> shard_run_arguments(const ShardRunFlags& flags) {
  std::vector<std::string> arguments;
  if (flags.no_snapshots)
    arguments.push_back("--no-snapshots");
  if (flags.workers > 0)
    arguments.insert(arguments.end(), {"--workers", std::to_string(flags.workers)});
  if (flags.timeout_seconds)
    arguments.insert(arguments.end(), {"--timeout", fmt::format("{}", *flags.timeout_seconds)});
  return arguments;
}

std::string format_submission(const SlurmSubmitResult& result, const std::filesystem::path& dir) {
  std::string command;
  for (const auto& arg : result.sbatch_command)
    command += (command.empty() ? "" : " ") + shell_quote(arg);
  std::string text;
  if (result.submitted) {
    text = fmt::format("Submitted Slurm job {}: array {}\n", result.slurm_job_id, result.array);
  } else {
    text = fmt::format("Dry run: not submitted. To submit:\n  {}\n", command);
  }
  const auto absolute = std::filesystem::absolute(dir).lexically_normal().string();
  return text + fmt::format(
                    "  script:   {}\n  manifest: {}\n  logs:     {}/slurm/shard-<I>.log\n"
                    "  status:   holebench slurm status --out {}\n"
                    "  merge:    holebench merge --shards {}\n",
                    result.script.string(), result.manifest.string(), absolute, absolute, absolute);
}

}  // namespace holebench::harness
