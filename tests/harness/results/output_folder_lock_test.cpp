// One run per output folder (harness/results/output_folder_lock.h): a second lock of a locked
// folder is refused with the holder's pid, from this process or another; the lock goes with its
// holder however the holder ends (SIGKILL included), and children the holder forks do not
// keep it. End to end with the holebench binary: a second `holebench run` into a folder in
// use exits with code 2 naming the holder, and once the holder is killed a `--resume` run
// takes the folder at once.
#include "harness/results/output_folder_lock.h"

#include "harness/run/run_jobs.h"

#include <gtest/gtest.h>

#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fcntl.h>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace holebench::harness {
namespace {

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_lock_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Whether OutputFolderLock(dir) is refused, and with which holder pid (0: it was not).
long refused_by(const std::filesystem::path& dir) {
  try {
    const OutputFolderLock lock(dir);
    return 0;
  } catch (const OutputFolderInUse& e) {
    return e.holder_pid();
  }
}

void kill_and_reap(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
}

TEST(OutputFolderLock, ASecondLockIsRefusedWithTheHoldersPid) {
  const auto dir = fresh_dir("same_process");
  {
    const OutputFolderLock lock(dir);
    EXPECT_TRUE(std::filesystem::is_directory(dir));  // created
    EXPECT_EQ(lock.lock_file(), dir / ".holebench.lock");
    EXPECT_EQ(std::stol(read_text(lock.lock_file())), ::getpid());
    try {
      const OutputFolderLock second(dir);
      ADD_FAILURE() << "locked twice";
    } catch (const OutputFolderInUse& e) {
      EXPECT_EQ(e.holder_pid(), ::getpid());
      EXPECT_EQ(e.dir(), dir);
      EXPECT_EQ(std::string(e.what()),
                dir.string() + " is in use by another holebench process (pid " +
                    std::to_string(::getpid()) + "); wait for it or choose another --out");
    }
    // A run into the folder is refused before it runs anything.
    RunOptions options;
    options.out_dir = dir;
    options.suite.case_patterns = {"box/corner"};
    options.suite.methods = {"liepa_cgal"};
    options.suite.include_cad = false;
    EXPECT_THROW(run_jobs(options), OutputFolderInUse);
    EXPECT_FALSE(std::filesystem::exists(dir / "records.jsonl"));
  }
  EXPECT_EQ(refused_by(dir), 0);  // released with its holder
}

// Another process holds the folder: refused with that process's pid; after it is killed
// with SIGKILL (no destructor runs) the folder can be locked at once.
TEST(OutputFolderLock, AnotherProcessHoldsItUntilItIsKilled) {
  const auto dir = fresh_dir("other_process");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t holder = ::fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {
    ::close(ready[0]);
    try {
      const OutputFolderLock lock(dir);
      const char byte = 1;
      if (::write(ready[1], &byte, 1) != 1)
        std::_Exit(3);
      for (;;)
        ::pause();
    } catch (...) {
      std::_Exit(2);
    }
  }
  ::close(ready[1]);
  char byte = 0;
  ASSERT_EQ(::read(ready[0], &byte, 1), 1) << "the holder could not lock the folder";
  ::close(ready[0]);

  EXPECT_EQ(refused_by(dir), holder);
  kill_and_reap(holder);
  EXPECT_EQ(refused_by(dir), 0);
}

// The holder's children (the runner's workers) do not keep the lock: with the holder killed
// and its child still alive, the folder is free.
TEST(OutputFolderLock, ChildrenOfTheHolderDoNotKeepIt) {
  const auto dir = fresh_dir("children");
  int ready[2];
  ASSERT_EQ(::pipe(ready), 0);
  const pid_t holder = ::fork();
  ASSERT_GE(holder, 0);
  if (holder == 0) {
    ::close(ready[0]);
    try {
      const OutputFolderLock lock(dir);
      if (::fork() == 0) {
        // The worker: tells its pid once it runs (its copy of the lock is closed by then).
        const pid_t self = ::getpid();
        if (::write(ready[1], &self, sizeof self) != sizeof self)
          std::_Exit(3);
        for (;;)
          ::pause();
      }
      for (;;)
        ::pause();
    } catch (...) {
      std::_Exit(2);
    }
  }
  ::close(ready[1]);
  pid_t worker = 0;
  ASSERT_EQ(::read(ready[0], &worker, sizeof worker), static_cast<ssize_t>(sizeof worker));
  ::close(ready[0]);

  EXPECT_EQ(refused_by(dir), holder);
  kill_and_reap(holder);
  EXPECT_EQ(::kill(worker, 0), 0) << "the worker should still be running";
  EXPECT_EQ(refused_by(dir), 0);
  ::kill(worker, SIGKILL);
}

// Starts `holebench ARGS` with stdout and stderr into `log`; returns its pid.
pid_t start_holebench(const std::vector<std::string>& args, const std::filesystem::path& log) {
  std::vector<std::string> argv_text{HOLEBENCH_BINARY};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& arg : argv_text)
    argv.push_back(arg.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
  pid_t pid = -1;
  const int error = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return error == 0 ? pid : -1;
}

// The exit code of `holebench ARGS` (-1 if it did not exit normally).
int run_holebench(const std::vector<std::string>& args, const std::filesystem::path& log) {
  const pid_t pid = start_holebench(args, log);
  if (pid < 0)
    return -1;
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(OutputFolderLock, TheRunCommandRefusesASecondRunAndResumesAfterAKill) {
  const auto dir = fresh_dir("command");
  const auto logs = fresh_dir("command_logs");
  std::filesystem::create_directories(logs);
  // 18 jobs, one at a time: the run is still going when the second one tries.
  const std::vector<std::string> run{
      "run",        "--out",   dir.string(), "--case",  "box/*", "--method",
      "liepa_cgal", "--noise", "0",          "--noise", "5",     "--noise",
      "25",         "--seed",  "0",          "--seed",  "1",     "--no-snapshots",
      "--no-cad",   "-j",      "1"};
  const pid_t first = start_holebench(run, logs / "first.log");
  ASSERT_GT(first, 0);
  // Wait until it holds the folder and has finished a job.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  const auto lock_file = dir / kOutputFolderLockName;
  while ((read_text(lock_file) != std::to_string(first) + "\n" ||
          read_text(dir / "records.jsonl").empty()) &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  ASSERT_FALSE(read_text(dir / "records.jsonl").empty()) << read_text(logs / "first.log");

  std::vector<std::string> resume = run;
  resume.push_back("--resume");
  EXPECT_EQ(run_holebench(resume, logs / "second.log"), 2);
  const std::string refusal = read_text(logs / "second.log");
  EXPECT_NE(refusal.find("holebench run: " + dir.string() +
                         " is in use by another holebench process (pid " + std::to_string(first) +
                         "); wait for it or choose another --out"),
            std::string::npos)
      << refusal;

  kill_and_reap(first);
  EXPECT_EQ(run_holebench(resume, logs / "third.log"), 0) << read_text(logs / "third.log");
  const std::string summary = read_text(logs / "third.log");
  EXPECT_NE(summary.find("18 jobs"), std::string::npos) << summary;
}

}  // namespace
}  // namespace holebench::harness
