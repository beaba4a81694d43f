#include "harness/run/process_pool.h"

#include "core/stopwatch.h"
#include "harness/results/record_json.h"

#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <stdexcept>
#include <thread>
#include <tuple>

namespace holebench::harness {

std::vector<JobRecord> read_records_jsonl(const std::filesystem::path& path) {
  std::vector<JobRecord> records;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    if (line.empty())
      continue;
    try {
      records.push_back(record_from_json_text(line));
    } catch (const std::exception&) {
      // A line cut short by an interruption: the job runs again.
    }
  }
  return records;
}

namespace {

using Clock = SteadyClock;

struct Child {
  pid_t pid = -1;
  int pipe_fd = -1;
  Clock::time_point started;
  std::string output;
  bool timed_out = false;
  /// The pipe gave its end of file (the child closed it, and is ending): it is no longer
  /// polled, since it would wake the poll at once, again and again, until the child is gone.
  bool pipe_ended = false;
  std::filesystem::path temporary_dir;  ///< the child's TMPDIR, removed when it ends
};

// How long a poll waits: 100 ms while every pipe is open (a record wakes it earlier), 1 ms
// once a child has closed its pipe and is ending, to reap it soon without spinning on a core
// that a job may need.
constexpr int kPollMilliseconds = 100;
constexpr int kEndingPollMilliseconds = 1;

// The entry that polls a child's pipe (none once the pipe has ended).
pollfd pipe_poll_entry(const Child& child) {
  return {child.pipe_ended ? -1 : child.pipe_fd, POLLIN, 0};
}

// Reads what a child's pipe holds after a poll said it is ready: true when it gave data
// (appended to the child's output); false at its end, which is then recorded.
bool read_ready_pipe(Child& child) {
  char buffer[65536];
  const ssize_t n = ::read(child.pipe_fd, buffer, sizeof(buffer));
  if (n > 0) {
    child.output.append(buffer, static_cast<std::size_t>(n));
    return true;
  }
  if (n == 0 || errno != EINTR)
    child.pipe_ended = true;
  return false;
}

// A fresh folder for one job's temporary files (an external method's mesh files): the job
// sees it as TMPDIR, and the runner removes it when the job ends, even when it was stopped.
std::filesystem::path make_job_temporary_dir() {
  std::string pattern = (std::filesystem::temp_directory_path() / "holebench-job-XXXXXX").string();
  if (!::mkdtemp(pattern.data()))
    throw std::runtime_error("mkdtemp " + pattern + ": " + std::strerror(errno));
  return pattern;
}

// Writes all of `text`; the error number of a failed write, 0 when all was written.
int write_all(int fd, const std::string& text) {
  const char* data = text.data();
  std::size_t left = text.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, data, left);
    if (n < 0) {
      if (errno == EINTR)
        continue;
      return errno;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

// Appends a record's line to records.jsonl and flushes it to disk; a failure (disk full)
// stops the run with an error naming the file: the records before it are kept.
void append_record(int fd, const std::string& line, const std::filesystem::path& path) {
  int error = write_all(fd, line);
  if (!error && ::fsync(fd) != 0 && errno != EINVAL)
    error = errno;
  if (error) {
    throw std::runtime_error("cannot append to " + path.string() + ": " + std::strerror(error) +
                             " (the records before this one are kept; --resume continues)");
  }
}

// The record of a job whose allocation failed in the child.
JobRecord out_of_memory_record(const Job& job, const std::string& what) {
  JobRecord record;
  record.job = job;
  record.user = job.user;
  record.status = JobStatus::OutOfMemory;
  record.message = "an allocation failed (" + what + ")";
  return record;
}

// Starts `body` in a child process that writes to the returned pipe and then ends. The
// child dies with its parent, leads a process group of its own, has its own TMPDIR and the
// memory limit.
Child start_child_process(const std::function<void(int fd)>& body,
                          std::uint64_t memory_limit_bytes) {
  const std::filesystem::path temporary_dir = make_job_temporary_dir();
  int fds[2];
  if (::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  std::fflush(nullptr);
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0)
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  if (pid == 0) {
    // A worker ends with its run: a run killed outright (SIGKILL, no chance to stop its
    // workers) leaves no worker behind writing into the output folder the next run takes.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent)
      std::_Exit(1);
    // Its own process group, which the processes it starts (an external method's program
    // and that program's children) join: a timeout stops them all.
    ::setpgid(0, 0);
    ::setenv("TMPDIR", temporary_dir.c_str(), 1);
    ::close(fds[0]);
    // The job's memory limit, inherited by every program it starts.
    apply_memory_limit(memory_limit_bytes);
    // Nothing may escape the child: it must never return into the parent's code, nor run
    // the parent's atexit handlers or destructors.
    try {
      body(fds[1]);
    } catch (...) {
    }
    ::close(fds[1]);
    std::_Exit(0);
  }
  ::setpgid(pid, pid);  // also here: the group exists before any kill (either call may be first)
  ::close(fds[1]);
  Child child;
  child.pid = pid;
  child.pipe_fd = fds[0];
  child.started = Clock::now();
  child.temporary_dir = temporary_dir;
  return child;
}

// Runs one job in the calling (child) process and writes its record as a line to `fd`, with
// the time of the heap warm-up before it (when there was one) as its first stage.
void run_job_and_send(const Job& job, const JobFunction& run_one, int fd,
                      std::optional<double> heap_warmup_seconds = std::nullopt) {
  JobRecord record;
  try {
    record = run_one(job);
  } catch (const std::bad_alloc& e) {
    record = out_of_memory_record(job, e.what());
  } catch (const std::exception& e) {
    record.job = job;
    record.status = JobStatus::Error;
    record.message = std::string("uncaught exception: ") + e.what();
  } catch (...) {
    record.job = job;
    record.status = JobStatus::Error;
    record.message = "uncaught exception of unknown type";
  }
  if (heap_warmup_seconds)
    record.stages.insert(record.stages.begin(), {stage_names::kHeapWarmup, *heap_warmup_seconds});
  write_all(fd, record_to_json_line(record) + "\n");
}

// The record of a child that ended: parsed from its output, or a crash/timeout record.
// The record of a job whose process (`process`: "the job's process", or its group's) ended
// without sending one: stopped past the time limit (`timeout_message`), killed by a SIGKILL
// the runner did not send (the kernel's out-of-memory killer), or dead by a signal or exit.
JobRecord record_without_output(const Job& job, int wait_status, bool timed_out,
                                const std::string& process, const std::string& timeout_message) {
  JobRecord record;
  record.job = job;
  record.user = job.user;
  if (timed_out) {
    record.status = JobStatus::Timeout;
    record.message = timeout_message;
  } else if (WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGKILL) {
    record.status = JobStatus::OutOfMemory;
    record.message = process +
                     " was killed (SIGKILL, not sent by the runner): most likely by the kernel's "
                     "out-of-memory killer";
  } else if (WIFSIGNALED(wait_status)) {
    record.status = JobStatus::Crash;
    record.message = process + " died: " + strsignal(WTERMSIG(wait_status));
  } else {
    record.status = JobStatus::Crash;
    record.message = process + " ended without a record (exit code " +
                     std::to_string(WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1) + ")";
  }
  return record;
}

JobRecord finish_child(const Child& child, const Job& job, int wait_status) {
  if (!child.timed_out && !child.output.empty()) {
    try {
      return record_from_json_text(child.output);
    } catch (const std::exception&) {
    }
  }
  return record_without_output(job, wait_status, child.timed_out, "the job's process",
                               "stopped after the time limit");
}

// When the child has ended: collects the rest of its output, closes its pipe, removes its
// TMPDIR, sets its wait status and returns true.
bool reap_if_ended(Child& child, int& status) {
  if (::waitpid(child.pid, &status, WNOHANG) != child.pid)
    return false;
  char buffer[65536];
  for (ssize_t n; (n = ::read(child.pipe_fd, buffer, sizeof(buffer))) > 0;)
    child.output.append(buffer, static_cast<std::size_t>(n));
  ::close(child.pipe_fd);
  std::error_code ignored;
  std::filesystem::remove_all(child.temporary_dir, ignored);
  return true;
}

// Waits for a child to end, collecting its output, and stops it (its process group) past
// `timeout_seconds` (0: no limit). The child's wait status.
int wait_for_child(Child& child, double timeout_seconds) {
  for (;;) {
    pollfd fd = pipe_poll_entry(child);
    ::poll(&fd, 1, child.pipe_ended ? kEndingPollMilliseconds : kPollMilliseconds);
    if ((fd.revents & (POLLIN | POLLHUP | POLLERR)) && read_ready_pipe(child))
      continue;
    if (timeout_seconds > 0 && seconds_since(child.started) > timeout_seconds && !child.timed_out) {
      ::kill(-child.pid, SIGKILL);
      child.timed_out = true;
    }
    int status = 0;
    if (reap_if_ended(child, status))
      return status;
  }
}

// A job forked from its group's process shares that process's memory until it writes to it:
// its first writes to the heap (the allocator reusing memory the group's process freed, given
// back to the kernel by release_free_heap_pages() below) each fault a page in, a cost that a
// job making its own case paid while making it. Taken here, before the job starts, by writing
// to the memory the allocator hands out first, so that the method's time does not carry it
// (ProcessPoolOptions::job_heap_warmup_bytes).
void copy_inherited_heap_pages(std::size_t bytes) {
  constexpr std::size_t kBlock = 16 * 1024;
  constexpr std::size_t kPage = 4096;
  std::vector<char*> blocks;
  blocks.reserve(bytes / kBlock);
  for (std::size_t taken = 0; taken < bytes; taken += kBlock) {
    auto* block = static_cast<char*>(std::malloc(kBlock));
    if (!block)
      break;
    for (std::size_t offset = 0; offset < kBlock; offset += kPage)
      static_cast<volatile char*>(block)[offset] = 0;
    blocks.push_back(block);
  }
  for (auto it = blocks.rbegin(); it != blocks.rend(); ++it)
    std::free(*it);
}

// The group's process, once its case is made, gives the kernel back the pages of the heap it
// freed (glibc's malloc_trim: the free top of the heap, and every whole free page inside it).
// A job's process reuses those free chunks first; where their pages are still the group's,
// each first write copies one (a copy-on-write fault), where they were given back it is a new
// zeroed page, with nothing to copy. The values computed are the same; docs/reliability.md
// has the figures.
void release_free_heap_pages() {
  malloc_trim(0);
}

// The line a group's process writes once its shared part is prepared (the case made).
constexpr const char* kPreparedLine = "prepared";

// The body of a group's process: prepares what the group's jobs share once, says so, then
// runs each job in a child process of its own, one after the other, each under the job's
// timeout, and writes each record as a line to `fd` as it ends; then ends the process.
[[noreturn]] void run_group(const std::vector<Job>& group, const GroupFunction& prepare,
                            const ProcessPoolOptions& options, int fd) {
  JobFunction run_one;
  try {
    run_one = prepare(group);
  } catch (const std::bad_alloc& e) {
    run_one = [what = std::string(e.what())](const Job& job) {
      return out_of_memory_record(job, what);
    };
  } catch (const std::exception& e) {
    run_one = [what = std::string(e.what())](const Job& job) -> JobRecord {
      throw std::runtime_error("preparing the job's case: " + what);
    };
  }
  write_all(fd, std::string(kPreparedLine) + "\n");
  release_free_heap_pages();
  for (const Job& job : group) {
    Child child = start_child_process(
        [&job, &run_one, &options](int job_fd) {
          const auto warmup_start = Clock::now();
          copy_inherited_heap_pages(options.job_heap_warmup_bytes);
          run_job_and_send(job, run_one, job_fd,
                           options.job_heap_warmup_bytes > 0
                               ? std::optional<double>(seconds_since(warmup_start))
                               : std::nullopt);
        },
        options.memory_limit_bytes);
    const int status = wait_for_child(child, options.timeout_seconds);
    // The job's own line as it sent it, when it sent one; else the record of how it ended.
    std::string line;
    if (!child.timed_out && !child.output.empty()) {
      try {
        record_from_json_text(child.output);
        line = child.output;
      } catch (const std::exception&) {
      }
    }
    if (line.empty())
      line = record_to_json_line(finish_child(child, job, status)) + "\n";
    write_all(fd, line);
  }
  // Every record sent: the process ends here, leaving what it made (the case, its
  // evaluation's tables and scenes) to the kernel, which takes it back at once; freeing it
  // piece by piece took about as long as forking a job.
  ::close(fd);
  std::_Exit(0);
}

// A group's process as the runner sees it: its jobs (indices into the plan, in the order
// it runs them) and how far it got.
struct RunningGroup {
  Child process;
  std::vector<std::size_t> job_indices;
  std::size_t records_received = 0;
  bool prepared = false;
  Clock::time_point last_progress;
};

// The record of a job of a group whose process ended (or was stopped) before sending it.
JobRecord unfinished_group_record(const RunningGroup& group, const Job& job, int wait_status) {
  return record_without_output(
      job, wait_status, group.process.timed_out, "the process making the job's case",
      group.prepared ? "stopped after the time limit (its group's process hung)"
                     : "stopped after the time limit while making its case");
}

// Opens the records file for appending: with `resume`, the records already in it are read into
// `done` (and a line cut short by an interruption is ended, so that the next record starts a
// line); else it is started afresh. Returns its descriptor.
int open_records_file(const std::filesystem::path& records_path, bool resume,
                      std::map<std::string, JobRecord>& done) {
  if (resume) {
    for (auto& record : read_records_jsonl(records_path))
      done[record.job.id()] = std::move(record);
  } else {
    std::filesystem::remove(records_path);
  }
  const int fd = ::open(records_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot write " + records_path.string() + ": " + std::strerror(errno));
  std::ifstream existing(records_path, std::ios::binary | std::ios::ate);
  if (existing && existing.tellg() > 0) {
    existing.seekg(-1, std::ios::end);
    if (existing.get() != '\n')
      append_record(fd, "\n", records_path);
  }
  return fd;
}

// The jobs still to run (not in `done`), in groups of equal `group_of` key (each alone
// without one), in the order of each group's first job, as indices into `jobs`; counts the
// jobs found done in `*resumed`.
std::vector<std::vector<std::size_t>> group_pending_jobs(
    const std::vector<Job>& jobs, const std::map<std::string, JobRecord>& done,
    const GroupKeyFunction& group_of, std::size_t* resumed) {
  std::vector<std::vector<std::size_t>> groups;
  std::map<std::string, std::size_t> group_by_key;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    if (done.count(jobs[i].id())) {
      ++*resumed;
      continue;
    }
    if (!group_of) {
      groups.push_back({i});
      continue;
    }
    const auto [it, added] = group_by_key.emplace(group_of(jobs[i]), groups.size());
    if (added)
      groups.emplace_back();
    groups[it->second].push_back(i);
  }
  return groups;
}

// Starts the process of a group of jobs (indices into `jobs`): it prepares their case once and
// runs each job in a child of its own (run_group).
RunningGroup start_group(const std::vector<Job>& jobs, const std::vector<std::size_t>& indices,
                         const GroupFunction& prepare, const ProcessPoolOptions& options) {
  RunningGroup group;
  group.job_indices = indices;
  std::vector<Job> group_jobs;
  for (std::size_t index : group.job_indices)
    group_jobs.push_back(jobs[index]);
  group.process =
      start_child_process([&group_jobs, &prepare, &options](
                              int group_fd) { run_group(group_jobs, prepare, options, group_fd); },
                          options.memory_limit_bytes);
  group.last_progress = Clock::now();
  return group;
}

// The record a group's process sent for `job` as a line; where it does not read back, an
// error record saying so.
JobRecord record_of_line(const std::string& line, const Job& job) {
  try {
    return record_from_json_text(line);
  } catch (const std::exception& e) {
    JobRecord record;
    record.job = job;
    record.user = job.user;
    record.status = JobStatus::Error;
    record.message = std::string("the job's record did not read back: ") + e.what();
    return record;
  }
}

class Progress {
 public:
  /// `already_done`: jobs kept from an earlier run (--resume): counted as done, but not
  /// in the rate, which is this run's.
  Progress(std::size_t total, std::size_t already_done, bool enabled)
      : total_(total), already_done_(already_done), enabled_(enabled), tty_(::isatty(2)) {}

  void update(std::size_t done, std::size_t failures, const std::string& last) {
    if (!enabled_)
      return;
    const double elapsed = seconds_since(start_);
    const std::size_t done_now = done > already_done_ ? done - already_done_ : 0;
    const double rate = elapsed > 0 ? done_now / elapsed : 0.0;
    const double eta = rate > 0 ? (total_ - done) / rate : 0.0;
    const int width = 28;
    const int filled = total_ ? static_cast<int>(width * done / total_) : width;
    char line[512];
    std::snprintf(line, sizeof(line), "[%s%s] %zu/%zu  %.2f jobs/s  ETA %dm%02ds  failures %zu  %s",
                  std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(), done,
                  total_, rate, static_cast<int>(eta) / 60, static_cast<int>(eta) % 60, failures,
                  last.c_str());
    if (tty_) {
      std::fprintf(stderr, "\r%-150.150s", line);
      if (done == total_)
        std::fprintf(stderr, "\n");
    } else {
      // A log file: a line per job for short runs, every 2 % for long ones.
      const std::size_t step = std::max<std::size_t>(1, total_ / 50);
      if (done % step == 0 || done == total_)
        std::fprintf(stderr, "%s\n", line);
    }
  }

 private:
  std::size_t total_;
  std::size_t already_done_;
  bool enabled_;
  bool tty_;
  Clock::time_point start_ = Clock::now();
};

}  // namespace

ProcessPoolResult run_isolated(const std::vector<Job>& jobs, const JobFunction& run_one,
                               const std::filesystem::path& records_path,
                               const ProcessPoolOptions& options) {
  const GroupFunction prepare = [&run_one](const std::vector<Job>&) { return run_one; };
  ProcessPoolOptions alone = options;
  alone.job_heap_warmup_bytes = 0;  // nothing made before the job: nothing to copy
  return run_grouped(jobs, nullptr, prepare, records_path, alone);
}

int worker_count_of(int workers) {
  return workers > 0 ? workers : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

ProcessPoolResult run_grouped(const std::vector<Job>& jobs, const GroupKeyFunction& group_of,
                              const GroupFunction& prepare,
                              const std::filesystem::path& records_path,
                              const ProcessPoolOptions& options) {
  const auto start = Clock::now();
  ProcessPoolResult result;
  std::map<std::string, JobRecord> done;
  const int fd = open_records_file(records_path, options.resume, done);
  const auto groups = group_pending_jobs(jobs, done, group_of, &result.resumed);
  std::set<std::string> wanted;
  for (const auto& job : jobs)
    wanted.insert(job.id());
  const int workers = worker_count_of(options.workers);
  Progress progress(jobs.size(), result.resumed, options.progress);
  std::size_t finished = result.resumed;
  std::size_t failures = 0;
  for (const auto& [id, record] : done)
    failures += wanted.count(id) && record.status != JobStatus::Ok ? 1 : 0;

  const auto take = [&](JobRecord record) {
    const Job& job = record.job;
    if (record.case_family.empty() && options.case_family_kind)
      std::tie(record.case_family, record.case_kind) = options.case_family_kind(job.case_id);
    append_record(fd, record_to_json_line(record) + "\n", records_path);
    failures += record.status != JobStatus::Ok ? 1 : 0;
    ++finished;
    progress.update(finished, failures, job.id() + " " + to_string(record.status));
    done[job.id()] = std::move(record);
  };
  // The complete lines a group's process sent: "prepared", then one record per job.
  const auto take_lines = [&](RunningGroup& group) {
    std::string& output = group.process.output;
    std::size_t line_start = 0;
    for (std::size_t end; (end = output.find('\n', line_start)) != std::string::npos;
         line_start = end + 1) {
      const std::string line = output.substr(line_start, end - line_start);
      group.last_progress = Clock::now();
      if (line == kPreparedLine) {
        group.prepared = true;
        continue;
      }
      if (group.records_received >= group.job_indices.size())
        continue;
      const Job& job = jobs[group.job_indices[group.records_received]];
      ++group.records_received;
      take(record_of_line(line, job));
    }
    output.erase(0, line_start);
  };

  std::vector<RunningGroup> running;
  std::size_t next = 0;
  while (next < groups.size() || !running.empty()) {
    while (next < groups.size() && static_cast<int>(running.size()) < workers)
      running.push_back(start_group(jobs, groups[next++], prepare, options));
    std::vector<pollfd> fds;
    bool any_ending = false;
    for (const auto& group : running) {
      fds.push_back(pipe_poll_entry(group.process));
      any_ending = any_ending || group.process.pipe_ended;
    }
    ::poll(fds.data(), fds.size(), any_ending ? kEndingPollMilliseconds : kPollMilliseconds);
    for (std::size_t g = 0; g < running.size(); ++g) {
      RunningGroup& group = running[g];
      Child& child = group.process;
      if ((fds[g].revents & (POLLIN | POLLHUP | POLLERR)) && read_ready_pipe(child)) {
        take_lines(group);
        continue;  // more may follow; the pipe closes when the process ends
      }
      // The group's process stops each job past the timeout itself; it is stopped here
      // only when it sends nothing for longer than that (making its case hung), with a
      // margin for stopping a job and sending its record.
      if (options.timeout_seconds > 0 && !child.timed_out &&
          seconds_since(group.last_progress) >
              options.timeout_seconds + options.group_stall_margin_seconds) {
        ::kill(-child.pid, SIGKILL);
        child.timed_out = true;
      }
      int status = 0;
      if (!reap_if_ended(child, status))
        continue;
      take_lines(group);
      for (std::size_t r = group.records_received; r < group.job_indices.size(); ++r)
        take(unfinished_group_record(group, jobs[group.job_indices[r]], status));
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(g));
      fds.erase(fds.begin() + static_cast<std::ptrdiff_t>(g));
      --g;
    }
  }
  ::close(fd);
  for (const auto& job : jobs)
    result.records.push_back(done.at(job.id()));
  result.failures = failures;
  result.seconds = seconds_since(start);
  return result;
}

}  // namespace holebench::harness
