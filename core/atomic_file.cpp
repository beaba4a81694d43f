#include "core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace holebench {

namespace {

[[noreturn]] void cannot_write(const std::filesystem::path& path, int error,
                               const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  throw std::runtime_error("cannot write " + path.string() + ": " +
                           (error ? std::strerror(error) : "the stream failed"));
}

// Flushes the file's data (or a folder's entries) to the disk; the error number, 0 if none.
int sync_path(const std::filesystem::path& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0)
    return errno;
  const int result = ::fsync(fd) == 0 ? 0 : errno;
  ::close(fd);
  return result;
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  const std::filesystem::path temporary = path.string() + ".partial";
  {
    errno = 0;
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out)
      cannot_write(path, errno, temporary);
    write(out);
    out.flush();
    if (!out)
      cannot_write(path, errno, temporary);
    out.close();
    if (!out)
      cannot_write(path, errno, temporary);
  }
  if (const int error = sync_path(temporary, O_RDONLY))
    cannot_write(path, error, temporary);
  std::error_code error;
  std::filesystem::rename(temporary, path, error);
  if (error)
    cannot_write(path, error.value(), temporary);
  const auto folder = path.parent_path().empty() ? std::filesystem::path(".") : path.parent_path();
  sync_path(folder, O_RDONLY | O_DIRECTORY);  // the rename itself; best effort
}

void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  write_file_atomically(path, [&text](std::ostream& out) { out << text; });
}

}  // namespace holebench
