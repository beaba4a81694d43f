#include "methods/external/program_run.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <utility>
#include <vector>

namespace holebench {

std::string ProgramRun::how_it_ended() const {
  if (!started)
    return "not started: " + error;
  if (signal != 0)
    return std::string("killed by ") + strsignal(signal);
  return "exit code " + std::to_string(exit_code);
}

ProgramRun run_shell_command(const std::string& command, const std::filesystem::path& stdout_path,
                             const std::filesystem::path& stderr_path) {
  ProgramRun run;
  const std::string out = stdout_path.string(), err = stderr_path.string();
  const pid_t parent = ::getpid();
  const pid_t pid = ::fork();
  if (pid < 0) {
    run.error = std::string("fork: ") + std::strerror(errno);
    return run;
  }
  if (pid == 0) {
    // Only async-signal-safe calls until exec (the parent may have threads).
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent)
      ::_exit(127);
    const int in_fd = ::open("/dev/null", O_RDONLY);
    const int out_fd = ::open(out.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    const int err_fd = ::open(err.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (in_fd < 0 || out_fd < 0 || err_fd < 0)
      ::_exit(127);
    ::dup2(in_fd, 0);
    ::dup2(out_fd, 1);
    ::dup2(err_fd, 2);
    ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    ::_exit(127);
  }
  run.started = true;
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) {
      run.started = false;
      run.error = std::string("waitpid: ") + std::strerror(errno);
      return run;
    }
  }
  if (WIFSIGNALED(status))
    run.signal = WTERMSIG(status);
  else
    run.exit_code = WEXITSTATUS(status);
  return run;
}

std::string last_lines(const std::filesystem::path& path, int count, std::size_t max_chars) {
  std::ifstream in(path, std::ios::binary);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    lines.push_back(std::move(line));
  }
  while (!lines.empty() && lines.back().empty())
    lines.pop_back();
  std::string tail;
  const std::size_t first =
      lines.size() > static_cast<std::size_t>(count) ? lines.size() - count : 0;
  for (std::size_t i = first; i < lines.size(); ++i)
    tail += (i == first ? "" : "\n") + lines[i];
  if (tail.size() > max_chars)
    tail = "..." + tail.substr(tail.size() - max_chars);
  return tail;
}

bool program_on_path(const std::string& program) {
  if (program.find('/') != std::string::npos)
    return ::access(program.c_str(), X_OK) == 0;
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin");
  for (std::string dir; std::getline(dirs, dir, ':');) {
    if (!dir.empty() && ::access((dir + "/" + program).c_str(), X_OK) == 0)
      return true;
  }
  return false;
}

}  // namespace holebench
