// Mesh file reading and writing with holebench's own parsers, so that every error names
// the file and the place (line for text, byte offset for binary data). The readers are one
// file per format in core/mesh_io/; here: formats by extension, reading a file, writing.
#include "core/mesh_io.h"

#include "core/errors.h"
#include "core/mesh_io/parsing.h"
#include "core/mesh_io/readers.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

namespace holebench {
namespace {

namespace fs = std::filesystem;
using mesh_io::fail;
using mesh_io::iequals;
using mesh_io::show;

// ------------------------------------------------------------------ reading files

void check_readable(const fs::path& path) {
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
    fail(path.string(), "the file does not exist");
  if (fs::is_directory(status))
    fail(path.string(), "is a directory, not a mesh file");
}

std::string read_file(const fs::path& path) {
  const std::string src = path.string();
  std::FILE* file = std::fopen(src.c_str(), "rb");
  if (file == nullptr)
    fail(src, fmt::format("cannot open the file: {}", std::strerror(errno)));
  std::string content;
  std::array<char, 1 << 16> chunk{};
  for (;;) {
    const std::size_t n = std::fread(chunk.data(), 1, chunk.size(), file);
    content.append(chunk.data(), n);
    if (n < chunk.size())
      break;
  }
  const bool error = std::ferror(file) != 0;
  std::fclose(file);
  if (error)
    fail(src, "cannot read the file (I/O error)");
  return content;
}

// ------------------------------------------------------------------ writing

/// A file written through a buffer; every failure throws std::runtime_error naming it.
class OutputFile {
 public:
  explicit OutputFile(const fs::path& path) : name_(path.string()) {
    file_ = std::fopen(name_.c_str(), "wb");
    if (file_ == nullptr) {
      throw std::runtime_error(
          fmt::format("{}: cannot open for writing: {}", name_, std::strerror(errno)));
    }
  }
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  ~OutputFile() {
    if (file_ != nullptr)
      std::fclose(file_);
  }

  template <typename... Args>
  void print(fmt::format_string<Args...> format, Args&&... args) {
    fmt::format_to(fmt::appender(buffer_), format, std::forward<Args>(args)...);
    if (buffer_.size() > (1 << 20))
      flush();
  }
  void bytes(const void* data, std::size_t n) {
    const char* p = static_cast<const char*>(data);
    buffer_.append(p, p + n);
    if (buffer_.size() > (1 << 20))
      flush();
  }
  void little_endian(std::uint64_t value, int size) {
    char b[8];
    for (int i = 0; i < size; ++i)
      b[i] = static_cast<char>((value >> (8 * i)) & 0xff);
    bytes(b, static_cast<std::size_t>(size));
  }
  void f32(float f) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    little_endian(bits, 4);
  }
  void f64(double d) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, 8);
    little_endian(bits, 8);
  }
  void close() {
    flush();
    const int rc = std::fclose(file_);
    file_ = nullptr;
    if (rc != 0)
      write_failed();
  }

 private:
  void flush() {
    if (buffer_.size() > 0 &&
        std::fwrite(buffer_.data(), 1, buffer_.size(), file_) != buffer_.size()) {
      write_failed();
    }
    buffer_.clear();
  }
  [[noreturn]] void write_failed() const {
    throw std::runtime_error(fmt::format("{}: cannot write: {}", name_, std::strerror(errno)));
  }

  std::string name_;
  std::FILE* file_ = nullptr;
  fmt::memory_buffer buffer_;
};

Point unit_normal(const TriangleSoup& soup, const std::array<int, 3>& tri) {
  const Point& a = soup.points[tri[0]];
  Point n = OpenMesh::cross(soup.points[tri[1]] - a, soup.points[tri[2]] - a);
  const double length = n.norm();
  return length > 0 ? n / length : Point(0, 0, 0);
}

void write_off(const TriangleSoup& soup, OutputFile& out) {
  out.print("OFF\n{} {} 0\n", soup.points.size(), soup.triangles.size());
  for (const Point& p : soup.points)
    out.print("{:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  for (const auto& t : soup.triangles)
    out.print("3 {} {} {}\n", t[0], t[1], t[2]);
}

void write_obj(const TriangleSoup& soup, OutputFile& out) {
  out.print("# written by holebench\n");
  for (const Point& p : soup.points)
    out.print("v {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
  for (const auto& t : soup.triangles)
    out.print("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
}

void write_stl_ascii(const TriangleSoup& soup, OutputFile& out) {
  out.print("solid holebench\n");
  for (const auto& t : soup.triangles) {
    const Point n = unit_normal(soup, t);
    out.print("  facet normal {:.9g} {:.9g} {:.9g}\n    outer loop\n", n[0], n[1], n[2]);
    for (int k = 0; k < 3; ++k) {
      const Point& p = soup.points[t[k]];
      out.print("      vertex {:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    }
    out.print("    endloop\n  endfacet\n");
  }
  out.print("endsolid holebench\n");
}

void write_stl_binary(const std::filesystem::path& path, const TriangleSoup& soup,
                      OutputFile& out) {
  if (soup.triangles.size() > std::numeric_limits<std::uint32_t>::max()) {
    throw std::runtime_error(fmt::format("{}: {} triangles do not fit in a binary STL",
                                         path.string(), soup.triangles.size()));
  }
  std::array<char, 80> header{};  // must not start with "solid"
  const std::string_view title = "binary STL written by holebench";
  std::copy(title.begin(), title.end(), header.begin());
  out.bytes(header.data(), header.size());
  out.little_endian(soup.triangles.size(), 4);
  for (const auto& t : soup.triangles) {
    const Point n = unit_normal(soup, t);
    for (int c = 0; c < 3; ++c)
      out.f32(static_cast<float>(n[c]));
    for (int k = 0; k < 3; ++k) {
      for (int c = 0; c < 3; ++c)
        out.f32(static_cast<float>(soup.points[t[k]][c]));
    }
    out.little_endian(0, 2);  // attribute byte count
  }
}

void write_ply(const TriangleSoup& soup, OutputFile& out, bool binary, bool regions) {
  out.print("ply\nformat {} 1.0\ncomment written by holebench\n",
            binary ? "binary_little_endian" : "ascii");
  out.print("element vertex {}\nproperty double x\nproperty double y\nproperty double z\n",
            soup.points.size());
  out.print("element face {}\nproperty list uchar int vertex_indices\n", soup.triangles.size());
  if (regions)
    out.print("property int region\n");
  out.print("end_header\n");
  const auto region_of = [&](std::size_t j) {
    return soup.regions.empty() ? kNoRegion : soup.regions[j];
  };
  for (const Point& p : soup.points) {
    if (binary) {
      for (int c = 0; c < 3; ++c)
        out.f64(p[c]);
    } else {
      out.print("{:.17g} {:.17g} {:.17g}\n", p[0], p[1], p[2]);
    }
  }
  for (std::size_t j = 0; j < soup.triangles.size(); ++j) {
    const auto& t = soup.triangles[j];
    if (binary) {
      out.little_endian(3, 1);
      for (int k = 0; k < 3; ++k)
        out.little_endian(static_cast<std::uint32_t>(t[k]), 4);
      if (regions)
        out.little_endian(static_cast<std::uint32_t>(region_of(j)), 4);
    } else if (regions) {
      out.print("3 {} {} {} {}\n", t[0], t[1], t[2], region_of(j));
    } else {
      out.print("3 {} {} {}\n", t[0], t[1], t[2]);
    }
  }
}

}  // namespace

MeshFormat format_from_extension(const std::filesystem::path& path) {
  const std::string extension = path.extension().string();
  if (iequals(extension, ".off"))
    return MeshFormat::Off;
  if (iequals(extension, ".obj"))
    return MeshFormat::Obj;
  if (iequals(extension, ".stl"))
    return MeshFormat::StlBinary;
  if (iequals(extension, ".ply"))
    return MeshFormat::PlyBinary;
  fail(path.string(),
       fmt::format("unknown mesh file extension {} (expected .off, .obj, .stl or .ply)",
                   extension.empty() ? std::string("(none)") : show(extension)));
}

TriangleSoup read_soup(const std::filesystem::path& path) {
  const std::string src = path.string();
  check_readable(path);
  const MeshFormat format = format_from_extension(path);
  const std::string content = read_file(path);
  if (content.empty())
    fail(src, "the file is empty");
  switch (format) {
    case MeshFormat::Off:
      return mesh_io::read_off(src, content);
    case MeshFormat::Obj:
      return mesh_io::read_obj(src, content);
    case MeshFormat::StlAscii:
    case MeshFormat::StlBinary:
      return mesh_io::read_stl(src, content);
    case MeshFormat::PlyAscii:
    case MeshFormat::PlyBinary:
      return mesh_io::read_ply(src, content);
  }
  fail(src, "unknown mesh format");
}

Mesh read_mesh(const std::filesystem::path& path) {
  return build_mesh(read_soup(path), BuildOptions{path.string()});
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
  MeshFormat format = format_from_extension(path);
  if (!options.binary && format == MeshFormat::StlBinary)
    format = MeshFormat::StlAscii;
  if (!options.binary && format == MeshFormat::PlyBinary)
    format = MeshFormat::PlyAscii;
  const TriangleSoup soup = to_soup(mesh);
  OutputFile out(path);
  switch (format) {
    case MeshFormat::Off:
      write_off(soup, out);
      break;
    case MeshFormat::Obj:
      write_obj(soup, out);
      break;
    case MeshFormat::StlAscii:
      write_stl_ascii(soup, out);
      break;
    case MeshFormat::StlBinary:
      write_stl_binary(path, soup, out);
      break;
    case MeshFormat::PlyAscii:
      write_ply(soup, out, false, options.write_regions);
      break;
    case MeshFormat::PlyBinary:
      write_ply(soup, out, true, options.write_regions);
      break;
  }
  out.close();
}

}  // namespace holebench