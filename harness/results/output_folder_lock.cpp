#include "harness/results/output_folder_lock.h"

#include <fcntl.h>
#include <pthread.h>
#include <sys/file.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>

namespace holebench::harness {
namespace {

// The descriptors of the locks this process holds (descriptor + 1; 0: a free slot; static
// storage starts zeroed). A fixed table of atomics, so that the fork handler in the child
// neither allocates nor takes a lock.
std::array<std::atomic<int>, 16> held_locks;

// In a forked child: close the copies of the held locks' descriptors (the parent keeps the
// locks) and forget them, so that nothing in the child releases or closes them again.
void close_held_locks_in_child() {
  for (auto& slot : held_locks) {
    const int stored = slot.exchange(0);
    if (stored > 0)
      ::close(stored - 1);
  }
}

void remember(int fd) {
  static std::once_flag installed;
  std::call_once(installed, [] { ::pthread_atfork(nullptr, nullptr, &close_held_locks_in_child); });
  for (auto& slot : held_locks) {
    int expected = 0;
    if (slot.compare_exchange_strong(expected, fd + 1))
      return;
  }
  // More than 16 folders locked at once: this one's descriptor is inherited by children.
}

// Whether `fd` was remembered by this process (false in a child, where it was closed).
bool forget(int fd) {
  for (auto& slot : held_locks) {
    int expected = fd + 1;
    if (slot.compare_exchange_strong(expected, 0))
      return true;
  }
  return false;
}

// The pid the lock file names; 0 if it names none. The holder writes it right after taking
// the lock, so an empty file is read again for a moment.
long holder_pid(const std::filesystem::path& path) {
  for (int attempt = 0; attempt < 20; ++attempt) {
    std::ifstream in(path);
    long pid = 0;
    if (in >> pid && pid > 0)
      return pid;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return 0;
}

std::string in_use_message(const std::filesystem::path& dir, long pid) {
  return dir.string() + " is in use by another holebench process (" +
         (pid > 0 ? "pid " + std::to_string(pid) : std::string("pid unknown")) +
         "); wait for it or choose another --out";
}

}  // namespace

OutputFolderInUse::OutputFolderInUse(const std::filesystem::path& dir, long holder_pid)
    : std::runtime_error(in_use_message(dir, holder_pid)), dir_(dir), holder_pid_(holder_pid) {}

OutputFolderLock::OutputFolderLock(const std::filesystem::path& dir)
    : path_(dir / kOutputFolderLockName) {
  std::filesystem::create_directories(dir);
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw std::runtime_error("cannot create " + path_.string() + ": " + std::strerror(errno));
  int result;
  do {
    result = ::flock(fd_, LOCK_EX | LOCK_NB);
  } while (result != 0 && errno == EINTR);
  if (result != 0) {
    const int error = errno;
    ::close(fd_);
    fd_ = -1;
    if (error == EWOULDBLOCK)
      throw OutputFolderInUse(dir, holder_pid(path_));
    throw std::runtime_error("cannot lock " + path_.string() + ": " + std::strerror(error));
  }
  remember(fd_);
  const std::string pid = std::to_string(::getpid()) + "\n";
  if (::ftruncate(fd_, 0) != 0 ||
      ::pwrite(fd_, pid.data(), pid.size(), 0) != static_cast<ssize_t>(pid.size())) {
    // The lock holds without the pid; others then report "pid unknown".
  }
}

OutputFolderLock::~OutputFolderLock() {
  // Only the process that took the lock releases it: closing the last descriptor of the open
  // file releases the flock. (A child never unlocks: that would release its parent's lock.)
  if (fd_ >= 0 && forget(fd_)) {
    if (::ftruncate(fd_, 0) != 0) {
      // A stale pid in an unlocked file misleads nobody: the lock is what counts.
    }
    ::close(fd_);
  }
}

}  // namespace holebench::harness
