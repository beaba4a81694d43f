// One run per output folder: `holebench run` (also with --resume) and `holebench merge` hold
// an exclusive lock on the folder they write for as long as they run, so that two processes
// never append to the same records.jsonl or overwrite each other's results.
//
// The lock is flock(LOCK_EX | LOCK_NB) on DIR/.holebench.lock, which holds the holder's pid as
// text. The kernel releases it when the holder's descriptor is closed, which happens when the
// process ends however it ends: a killed run (even by SIGKILL) does not block the next one.
// The file itself stays (removing it would let two processes lock two different files).
// Children the holder forks (the runner's workers) do not keep the lock: their copy of the
// descriptor is closed in the child at fork (pthread_atfork), so a worker that outlives a
// killed holder does not block the folder either. Exec'd programs never see it (O_CLOEXEC).
#pragma once

#include <filesystem>
#include <stdexcept>

namespace holebench::harness {

/// The lock file's name inside the output folder.
inline constexpr const char* kOutputFolderLockName = ".holebench.lock";

/// The folder is locked by another process (or another lock of this one).
class OutputFolderInUse : public std::runtime_error {
 public:
  /// `holder_pid`: as the lock file says; 0 when it does not say (yet).
  OutputFolderInUse(const std::filesystem::path& dir, long holder_pid);
  const std::filesystem::path& dir() const { return dir_; }
  long holder_pid() const { return holder_pid_; }

 private:
  std::filesystem::path dir_;
  long holder_pid_ = 0;
};

/// The exclusive lock of one output folder, held from construction to destruction.
class OutputFolderLock {
 public:
  /// Creates `dir` if missing and locks it without waiting. Throws OutputFolderInUse ("DIR is
  /// in use by another holebench process (pid N); wait for it or choose another --out") when
  /// it is locked already, std::runtime_error when the lock file cannot be created or locked.
  explicit OutputFolderLock(const std::filesystem::path& dir);
  ~OutputFolderLock();
  OutputFolderLock(const OutputFolderLock&) = delete;
  OutputFolderLock& operator=(const OutputFolderLock&) = delete;

  const std::filesystem::path& lock_file() const { return path_; }

 private:
  std::filesystem::path path_;
  int fd_ = -1;
};

}  // namespace holebench::harness
