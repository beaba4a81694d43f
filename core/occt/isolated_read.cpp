#include "core/occt/isolated_read.h"

#include "core/errors.h"
#include "core/occt/brep_file_reader.h"
#include "core/occt/shape_sewing.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace holebench::occt {
namespace {

// --- the child's answer: a tag, then the message or the soup, in the host's byte order ---

enum class Answer : std::uint8_t { Soup = 1, InvalidInput = 2, Error = 3 };

template <typename T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

void put_text(std::string& out, const std::string& text) {
  put(out, static_cast<std::uint64_t>(text.size()));
  out += text;
}

std::string encode(const TessellatedSoup& t) {
  std::string out;
  put(out, Answer::Soup);
  put(out, static_cast<std::uint64_t>(t.soup.points.size()));
  for (const Point& p : t.soup.points) {
    for (int i = 0; i < 3; ++i)
      put(out, static_cast<double>(p[i]));
  }
  put(out, static_cast<std::uint64_t>(t.soup.triangles.size()));
  for (const auto& triangle : t.soup.triangles) {
    for (int v : triangle)
      put(out, static_cast<std::int32_t>(v));
  }
  put(out, static_cast<std::uint64_t>(t.soup.regions.size()));
  for (int region : t.soup.regions)
    put(out, static_cast<std::int32_t>(region));
  put(out, static_cast<std::uint64_t>(t.face_surfaces.size()));
  for (SurfaceType type : t.face_surfaces)
    put(out, type);
  put(out, static_cast<std::uint64_t>(t.notes.size()));
  for (const std::string& note : t.notes)
    put_text(out, note);
  return out;
}

class Reader {
 public:
  explicit Reader(const std::string& bytes) : bytes_(bytes) {}
  template <typename T>
  T get() {
    if (at_ + sizeof(T) > bytes_.size())
      throw std::runtime_error("the answer is cut short");
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::size_t count(std::size_t element_size) {
    const auto n = get<std::uint64_t>();
    if (n > (bytes_.size() - at_) / element_size)
      throw std::runtime_error("the answer is cut short");
    return static_cast<std::size_t>(n);
  }
  std::string text() {
    const std::size_t n = count(1);
    std::string value = bytes_.substr(at_, n);
    at_ += n;
    return value;
  }

 private:
  const std::string& bytes_;
  std::size_t at_ = 0;
};

TessellatedSoup decode_soup(Reader& in) {
  TessellatedSoup t;
  t.soup.points.resize(in.count(3 * sizeof(double)));
  for (Point& p : t.soup.points) {
    for (int i = 0; i < 3; ++i)
      p[i] = in.get<double>();
  }
  t.soup.triangles.resize(in.count(3 * sizeof(std::int32_t)));
  for (auto& triangle : t.soup.triangles) {
    for (int& v : triangle)
      v = in.get<std::int32_t>();
  }
  t.soup.regions.resize(in.count(sizeof(std::int32_t)));
  for (int& region : t.soup.regions)
    region = in.get<std::int32_t>();
  t.face_surfaces.resize(in.count(sizeof(SurfaceType)));
  for (SurfaceType& type : t.face_surfaces)
    type = in.get<SurfaceType>();
  t.notes.resize(in.count(sizeof(std::uint64_t)));
  for (std::string& note : t.notes)
    note = in.text();
  return t;
}

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return;
    done += static_cast<std::size_t>(n);
  }
}

// Reads the file, sews its faces where they are not sewn, tessellates it.
TessellatedSoup read_and_tessellate(const std::filesystem::path& path,
                                    const TessellationOptions& options) {
  TopoDS_Shape shape = read_brep_shape(path);
  std::string sewing_note;
  if (options.sewing_tolerance_rel_diag > 0.0) {
    SewingResult sewing = sew_free_edges(shape, options.sewing_tolerance_rel_diag, path.string());
    shape = sewing.shape;
    sewing_note = sewing.note;
  }
  TessellatedSoup tessellated = tessellate_shape_soup(shape, options, path.string());
  if (!sewing_note.empty())
    tessellated.notes.insert(tessellated.notes.begin(), sewing_note);
  return tessellated;
}

// The child: read, tessellate, answer, leave without running the parent's atexit handlers.
[[noreturn]] void child_main(int fd, const std::filesystem::path& path,
                             const TessellationOptions& options) {
  std::string answer;
  try {
    answer = encode(read_and_tessellate(path, options));
  } catch (const InvalidInputError& e) {
    put(answer, Answer::InvalidInput);
    put_text(answer, e.what());
  } catch (const std::exception& e) {
    answer.clear();
    put(answer, Answer::Error);
    put_text(answer, e.what());
  } catch (...) {
    answer.clear();
    put(answer, Answer::Error);
    put_text(answer, "an exception of unknown type");
  }
  write_all(fd, answer);
  ::close(fd);
  std::_Exit(0);
}

// Everything the child writes until it closes the pipe; false when `seconds` (> 0) passed
// first.
bool read_all(int fd, double seconds, std::string& bytes) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds > 0 ? seconds : 0);
  char buffer[65536];
  for (;;) {
    if (seconds > 0) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
                            deadline - std::chrono::steady_clock::now())
                            .count();
      if (left <= 0)
        return false;
      pollfd wait{fd, POLLIN, 0};
      const int ready = ::poll(&wait, 1, static_cast<int>(std::min<long long>(left, 1000)));
      if (ready == 0 || (ready < 0 && errno == EINTR))
        continue;
    }
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR)
      continue;
    if (n <= 0)
      return true;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

}  // namespace

TessellatedSoup read_and_tessellate_isolated(const std::filesystem::path& path,
                                             const TessellationOptions& options) {
  int fds[2];
  if (::pipe(fds) != 0)
    throw std::runtime_error(std::string("pipe: ") + std::strerror(errno));
  const pid_t pid = ::fork();
  if (pid < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    throw std::runtime_error(std::string("fork: ") + std::strerror(errno));
  }
  if (pid == 0) {
    ::close(fds[0]);
    child_main(fds[1], path, options);
  }
  ::close(fds[1]);
  std::string bytes;
  const bool finished = read_all(fds[0], options.time_limit_seconds, bytes);
  ::close(fds[0]);
  if (!finished)
    ::kill(pid, SIGKILL);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!finished) {
    throw InvalidInputError(path.string() + ": OpenCASCADE did not finish reading it in " +
                            std::to_string(static_cast<int>(options.time_limit_seconds)) +
                            " s (the time limit): the file is damaged or too large");
  }
  if (WIFSIGNALED(status)) {
    throw InvalidInputError(path.string() + ": OpenCASCADE crashed reading it (" +
                            strsignal(WTERMSIG(status)) +
                            "): the file is damaged or of a kind OpenCASCADE cannot read");
  }
  try {
    Reader in(bytes);
    switch (in.get<Answer>()) {
      case Answer::Soup:
        return decode_soup(in);
      case Answer::InvalidInput:
        throw InvalidInputError(in.text());
      case Answer::Error:
        throw std::runtime_error(path.string() + ": " + in.text());
    }
  } catch (const std::runtime_error&) {
    if (bytes.empty()) {  // the child exited without writing (it cannot throw past child_main)
      throw InvalidInputError(path.string() +
                              ": the process reading it ended without an "
                              "answer (exit code " +
                              std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
    }
    throw;
  }
  throw InvalidInputError(path.string() + ": the process reading it gave an unknown answer");
}

}  // namespace holebench::occt
