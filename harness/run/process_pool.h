// The process pool that runs a plan: every job in its own process, so that an exception, a crash or
// a hang of a method becomes that job's status and the run goes on.
//
// Each child's address space is limited (ProcessPoolOptions::memory_limit_bytes, RLIMIT_AS:
// harness/run/memory_limit.h): a job that allocates past it gets the status out_of_memory
// (std::bad_alloc caught in the child, or the child killed by a SIGKILL the runner did not
// send: the kernel's out-of-memory killer), and the run goes on.
//
// Each job runs in a child process (fork) that sends its record back through a pipe. Jobs
// that share a case (run_grouped) run as a group: the runner keeps up to `workers` group
// processes running; each makes its case once and forks one child per job, one after the
// other. The process that started a job's child stops it when it passes the timeout (status
// timeout; the child leads a process group, and the whole group is stopped, so a program an
// external method started goes with it), and records a child that dies without a record
// (status crash, with the signal). A child dies with the runner's process
// (PR_SET_PDEATHSIG), so a run killed outright leaves no job running behind it. Each child has
// its own TMPDIR, a fresh folder removed when the child ends, so a stopped job leaves no
// temporary files (an external method's meshes) behind. Every finished
// record is appended to records.jsonl with one write on an O_APPEND descriptor and flushed to disk,
// so an interrupted run loses nothing and `resume` skips the jobs already there. Records depend
// only on their job: the same records come out whatever the number of workers (up to
// timings).
#pragma once

#include "harness/run/job.h"
#include "harness/run/memory_limit.h"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace holebench::harness {

struct ProcessPoolOptions {
  int workers = 0;                 ///< processes at once; 0: the number of cores
  double timeout_seconds = 300.0;  ///< per job; 0: none
  /// Address space of each job's process (RLIMIT_AS), in bytes; 0: none.
  std::uint64_t memory_limit_bytes = kDefaultMemoryLimitBytes;
  bool resume = false;   ///< keep the records already in records.jsonl
  bool progress = true;  ///< progress on stderr: done/total, rate, ETA, failures
  /// The family and kind of a case by its id, for the records the runner writes itself (a
  /// job that timed out or crashed sends none), so that reports group them with their case.
  /// Unset: they stay empty.
  std::function<std::pair<std::string, std::string>(const std::string& case_id)> case_family_kind;
  /// run_grouped: a group's process that sends nothing for the timeout plus this long (it
  /// hangs while preparing its case; it stops its jobs' children itself) is stopped.
  double group_stall_margin_seconds = 30.0;
  /// run_grouped: heap a job's process writes to before its job starts. A job forked from
  /// its group's process shares that process's memory until it writes to it, and each first
  /// write copies a page; a job that made its own case paid that while making it. Without
  /// this, the method's time would carry it (the fandisk's median liepa_cgal time 15 ms
  /// became 48 ms); 16 MiB brings it back (docs/reliability.md, "Jobs grouped by case").
  /// Its time is the record's `heap_warmup` stage.
  std::size_t job_heap_warmup_bytes = 16u << 20;
};

struct ProcessPoolResult {
  std::vector<JobRecord> records;  ///< one per job, in the order of `jobs`
  std::size_t resumed = 0;         ///< records taken from an earlier run
  std::size_t failures = 0;        ///< records whose status is not ok
  double seconds = 0.0;
};

using JobFunction = std::function<JobRecord(const Job&)>;

/// The processes that run at once for `workers`: itself, or one per core when 0.
int worker_count_of(int workers);

/// The group of a job: jobs with the same key share what `GroupFunction` prepares.
using GroupKeyFunction = std::function<std::string(const Job&)>;

/// Prepares, in a group's process and once, what the group's jobs share (their case), and
/// returns the function that runs one job of the group (in a child process of its own).
using GroupFunction = std::function<JobFunction(const std::vector<Job>& group)>;

/// Runs `jobs` with `run_one`, each in a child process, appending to `records_path`.
ProcessPoolResult run_isolated(const std::vector<Job>& jobs, const JobFunction& run_one,
                               const std::filesystem::path& records_path,
                               const ProcessPoolOptions& options);

/// Runs `jobs` in groups (`group_of`; nullptr: each job alone). A worker runs one group at a
/// time in a process of its own: it prepares the group's shared part once (`prepare`: the
/// case), then forks a child per job, one after the other, each stopped past the timeout and
/// each a crash of its own, and sends each record as it ends. A group's process that hangs
/// while preparing is stopped past the timeout (its jobs: status timeout), one that dies
/// gives its unfinished jobs the status crash. Records are the same as `run_isolated`'s.
ProcessPoolResult run_grouped(const std::vector<Job>& jobs, const GroupKeyFunction& group_of,
                              const GroupFunction& prepare,
                              const std::filesystem::path& records_path,
                              const ProcessPoolOptions& options);

/// The records in a records.jsonl file; lines that do not parse (a line cut short by an
/// interruption) are skipped.
std::vector<JobRecord> read_records_jsonl(const std::filesystem::path& path);

}  // namespace holebench::harness
