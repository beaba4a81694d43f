// Runs a shell command as a child process and reports how it ended. Used by external
// methods; the job's own process isolation and timeout (harness/run/process_pool.h) stay in
// charge: the command runs in the job's process group, so a job stopped at its time limit
// takes the command and its children with it, and it dies with the job's process.
#pragma once

#include <filesystem>
#include <string>

namespace holebench {

struct ProgramRun {
  bool started = false;  ///< false: fork failed (`error` says why)
  int exit_code = -1;    ///< the exit code, when it exited
  int signal = 0;        ///< the signal that ended it, or 0
  std::string error;

  bool succeeded() const { return started && signal == 0 && exit_code == 0; }
  /// "exit code 3", "killed by Segmentation fault", ...
  std::string how_it_ended() const;
};

/// Runs `/bin/sh -c command` in the current directory, stdin from /dev/null, stdout and
/// stderr appended to the files given; waits for it.
ProgramRun run_shell_command(const std::string& command, const std::filesystem::path& stdout_path,
                             const std::filesystem::path& stderr_path);

/// The last `count` lines of a text file (fewer if it has fewer; "" if it is missing), at
/// most `max_chars` characters (the end kept).
std::string last_lines(const std::filesystem::path& path, int count = 10,
                       std::size_t max_chars = 2000);

/// True if `program` is an executable found on PATH (or a path to one).
bool program_on_path(const std::string& program);

}  // namespace holebench
