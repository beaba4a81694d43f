#include "harness/run/process_pool.h"

#include "core/stopwatch.h"
#include "harness/results/record_json.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <new>
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
  std::size_t job_index = 0;
  Clock::time_point started;
  std::string output;
  bool timed_out = false;
  std::filesystem::path temporary_dir;  ///< the child's TMPDIR, removed when it ends
};

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

Child start_child(const Job& job, std::size_t index, const JobFunction& run_one,
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
    // The child: run the job, send its record, leave without running the parent's atexit
    // handlers or destructors.
    // Nothing may escape the child: it must never return into the parent's code.
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
    write_all(fds[1], record_to_json_line(record) + "\n");
    ::close(fds[1]);
    std::_Exit(0);
  }
  ::setpgid(pid, pid);  // also here: the group exists before any kill (either call may be first)
  ::close(fds[1]);
  Child child;
  child.pid = pid;
  child.pipe_fd = fds[0];
  child.job_index = index;
  child.started = Clock::now();
  child.temporary_dir = temporary_dir;
  return child;
}

// The record of a child that ended: parsed from its output, or a crash/timeout record.
JobRecord finish_child(const Child& child, const Job& job, int wait_status) {
  if (!child.timed_out && !child.output.empty()) {
    try {
      return record_from_json_text(child.output);
    } catch (const std::exception&) {
    }
  }
  JobRecord record;
  record.job = job;
  record.user = job.user;
  if (child.timed_out) {
    record.status = JobStatus::Timeout;
    record.message = "stopped after the time limit";
  } else if (WIFSIGNALED(wait_status) && WTERMSIG(wait_status) == SIGKILL) {
    // Not the runner's SIGKILL (that is a timeout): the kernel's out-of-memory killer.
    record.status = JobStatus::OutOfMemory;
    record.message =
        "the job's process was killed (SIGKILL, not sent by the runner): most likely by the "
        "kernel's out-of-memory killer";
  } else if (WIFSIGNALED(wait_status)) {
    record.status = JobStatus::Crash;
    record.message = std::string("the job's process died: ") + strsignal(WTERMSIG(wait_status));
  } else {
    record.status = JobStatus::Crash;
    record.message = "the job's process ended without a record (exit code " +
                     std::to_string(WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : -1) + ")";
  }
  return record;
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
  const auto start = Clock::now();
  ProcessPoolResult result;
  std::map<std::string, JobRecord> done;
  if (options.resume) {
    for (auto& record : read_records_jsonl(records_path))
      done[record.job.id()] = std::move(record);
  } else {
    std::filesystem::remove(records_path);
  }
  const int fd = ::open(records_path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0)
    throw std::runtime_error("cannot write " + records_path.string() + ": " + std::strerror(errno));
  // A line cut short by an interruption is ended, so that the next record starts a line.
  {
    std::ifstream existing(records_path, std::ios::binary | std::ios::ate);
    if (existing && existing.tellg() > 0) {
      existing.seekg(-1, std::ios::end);
      if (existing.get() != '\n')
        append_record(fd, "\n", records_path);
    }
  }

  std::vector<std::size_t> pending;
  std::set<std::string> wanted;
  for (std::size_t i = 0; i < jobs.size(); ++i) {
    wanted.insert(jobs[i].id());
    if (done.count(jobs[i].id())) {
      ++result.resumed;
    } else {
      pending.push_back(i);
    }
  }
  const int workers = options.workers > 0
                          ? options.workers
                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  Progress progress(jobs.size(), result.resumed, options.progress);
  std::size_t finished = result.resumed;
  std::size_t failures = 0;
  for (const auto& [id, record] : done)
    failures += wanted.count(id) && record.status != JobStatus::Ok ? 1 : 0;

  std::vector<Child> running;
  std::size_t next = 0;
  while (next < pending.size() || !running.empty()) {
    while (next < pending.size() && static_cast<int>(running.size()) < workers) {
      running.push_back(
          start_child(jobs[pending[next]], pending[next], run_one, options.memory_limit_bytes));
      ++next;
    }
    std::vector<pollfd> fds;
    for (const auto& child : running)
      fds.push_back({child.pipe_fd, POLLIN, 0});
    ::poll(fds.data(), fds.size(), 100);
    for (std::size_t c = 0; c < running.size(); ++c) {
      Child& child = running[c];
      if (fds[c].revents & (POLLIN | POLLHUP | POLLERR)) {
        char buffer[65536];
        const ssize_t n = ::read(child.pipe_fd, buffer, sizeof(buffer));
        if (n > 0)
          child.output.append(buffer, static_cast<std::size_t>(n));
        if (n > 0)
          continue;  // more may follow; the pipe closes when the child ends
      }
      const double elapsed = seconds_since(child.started);
      if (options.timeout_seconds > 0 && elapsed > options.timeout_seconds && !child.timed_out) {
        ::kill(-child.pid, SIGKILL);  // the job's process group
        child.timed_out = true;
      }
      int status = 0;
      const pid_t ended = ::waitpid(child.pid, &status, WNOHANG);
      if (ended != child.pid)
        continue;
      // Drain what is left in the pipe.
      char buffer[65536];
      for (ssize_t n; (n = ::read(child.pipe_fd, buffer, sizeof(buffer))) > 0;)
        child.output.append(buffer, n);
      ::close(child.pipe_fd);
      std::error_code ignored;
      std::filesystem::remove_all(child.temporary_dir, ignored);
      const Job& job = jobs[child.job_index];
      JobRecord record = finish_child(child, job, status);
      if (record.case_family.empty() && options.case_family_kind)
        std::tie(record.case_family, record.case_kind) = options.case_family_kind(job.case_id);
      append_record(fd, record_to_json_line(record) + "\n", records_path);
      failures += record.status != JobStatus::Ok ? 1 : 0;
      ++finished;
      progress.update(finished, failures, job.id() + " " + to_string(record.status));
      done[job.id()] = std::move(record);
      running.erase(running.begin() + static_cast<std::ptrdiff_t>(c));
      fds.erase(fds.begin() + static_cast<std::ptrdiff_t>(c));
      --c;
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
