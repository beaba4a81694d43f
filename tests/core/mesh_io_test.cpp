// Mesh file I/O: round trips in every format, hand-written files in every format, and an
// InvalidInputError that names the file and the place for every kind of bad input.
#include "core/mesh_io.h"
#include "core/errors.h"
#include "core/mesh.h"
#include "core/mesh_builder.h"

#include <fmt/format.h>
#include "tests/test_meshes.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace holebench {
namespace {

namespace fs = std::filesystem;

// ------------------------------------------------------------------ shapes and helpers

/// Bytes of a binary file, with integers and floats in either byte order.
class Bytes {
 public:
  Bytes& text(std::string_view s) {
    data_.append(s.data(), s.size());
    return *this;
  }
  Bytes& uint(std::uint64_t value, int size, bool big_endian = false) {
    for (int i = 0; i < size; ++i) {
      const int shift = 8 * (big_endian ? size - 1 - i : i);
      data_.push_back(static_cast<char>((value >> shift) & 0xff));
    }
    return *this;
  }
  Bytes& f32(float f, bool big_endian = false) {
    std::uint32_t bits = 0;
    std::memcpy(&bits, &f, 4);
    return uint(bits, 4, big_endian);
  }
  Bytes& f64(double d, bool big_endian = false) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &d, 8);
    return uint(bits, 8, big_endian);
  }
  const std::string& str() const { return data_; }

 private:
  std::string data_;
};

/// A binary STL: an 80-byte header starting with `title`, the declared triangle count and
/// the triangles given (each 50 bytes: normal, three corners, attribute).
std::string binary_stl(std::string_view title, std::uint32_t declared,
                       const std::vector<std::array<Point, 3>>& triangles) {
  Bytes bytes;
  std::string header(80, '\0');
  header.replace(0, title.size(), title);
  bytes.text(header).uint(declared, 4);
  for (const auto& t : triangles) {
    for (int c = 0; c < 3; ++c)
      bytes.f32(0.0f);
    for (const Point& p : t) {
      for (int c = 0; c < 3; ++c)
        bytes.f32(static_cast<float>(p[c]));
    }
    bytes.uint(0, 2);
  }
  return bytes.str();
}

std::vector<std::array<Point, 3>> corners_of(const TriangleSoup& soup) {
  std::vector<std::array<Point, 3>> out;
  for (const auto& t : soup.triangles) {
    out.push_back({soup.points[t[0]], soup.points[t[1]], soup.points[t[2]]});
  }
  return out;
}

/// A PNG signature and IHDR chunk: binary data that is no mesh.
std::string png_bytes() {
  Bytes bytes;
  bytes.text("\x89PNG\r\n\x1a\n").uint(13, 4, true).text("IHDR").uint(16, 4, true);
  bytes.uint(16, 4, true).uint(0x08060000, 4, true).uint(0x001f15c4, 4, true);
  for (int i = 0; i < 150; ++i)
    bytes.uint(static_cast<std::uint64_t>(i * 37 % 251), 1);
  return bytes.str();
}

/// Each test gets its own fresh directory under the system temporary directory.
class MeshIoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    static int counter = 0;
    const auto now = std::chrono::steady_clock::now().time_since_epoch().count();
    dir_ = fs::temp_directory_path() /
           fmt::format("holebench_mesh_io_{}_{}_{}", ::getpid(), now, counter++);
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }

  fs::path file(const std::string& name) const { return dir_ / name; }

  fs::path write(const std::string& name, std::string_view content) const {
    const fs::path path = file(name);
    std::ofstream out(path, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    EXPECT_TRUE(out.good()) << path;
    return path;
  }

  /// read_soup (or read_mesh) of `path` must throw InvalidInputError whose message starts
  /// with the path and contains every one of `parts`. Returns the message.
  static std::string expect_error(const fs::path& path, std::initializer_list<std::string> parts,
                                  bool whole_mesh = false) {
    std::string message;
    try {
      if (whole_mesh) {
        read_mesh(path);
      } else {
        read_soup(path);
      }
      ADD_FAILURE() << "no error reading " << path;
    } catch (const InvalidInputError& e) {
      message = e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "expected InvalidInputError reading " << path << ", got: " << e.what();
    }
    EXPECT_EQ(message.rfind(path.string() + ": ", 0), 0u) << message;
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "missing '" << part << "' in: " << message;
    }
    return message;
  }

  fs::path dir_;
};

void expect_same_points(const TriangleSoup& a, const TriangleSoup& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(a.points[i][c], b.points[i][c]) << "vertex " << i;
  }
}

// ------------------------------------------------------------------ format names

// Invariant: the extension (any case) selects the format; STL and PLY mean their binary forms.
TEST(FormatFromExtension, KnownAndUnknownExtensions) {
  EXPECT_EQ(format_from_extension("a/b.off"), MeshFormat::Off);
  EXPECT_EQ(format_from_extension("b.OBJ"), MeshFormat::Obj);
  EXPECT_EQ(format_from_extension("b.Stl"), MeshFormat::StlBinary);
  EXPECT_EQ(format_from_extension("b.ply"), MeshFormat::PlyBinary);
  EXPECT_THROW(format_from_extension("b.xyz"), InvalidInputError);
  EXPECT_THROW(format_from_extension("noextension"), InvalidInputError);
}

// ------------------------------------------------------------------ round trips

struct RoundTrip {
  const char* name;
  const char* file;
  bool binary;
  bool exact;    ///< coordinates exact (text and PLY double) or float precision (binary STL)
  bool merged;   ///< STL: vertices are renumbered by merging identical corners
  bool regions;  ///< region ids are kept (PLY)
};

class RoundTripTest : public MeshIoTest, public ::testing::WithParamInterface<RoundTrip> {};

// Invariant: write then read gives the same vertex and face counts and the same coordinates
// (exactly, or rounded to float for binary STL); non-STL formats keep the vertex order and
// the triangles; PLY keeps the region ids.
TEST_P(RoundTripTest, WriteThenReadGivesTheSameMesh) {
  const RoundTrip& param = GetParam();
  for (const TriangleSoup& original : {test::tetrahedron_soup(), test::octahedron_with_regions()}) {
    const fs::path path = file(param.file);
    WriteOptions options;
    options.binary = param.binary;
    write_mesh(build_mesh(original), path, options);

    const TriangleSoup soup = read_soup(path);
    ASSERT_EQ(soup.points.size(), original.points.size());
    ASSERT_EQ(soup.triangles.size(), original.triangles.size());
    if (param.merged) {
      // Corner by corner, triangle by triangle.
      const auto got = corners_of(soup);
      const auto want = corners_of(original);
      for (std::size_t t = 0; t < got.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
          for (int c = 0; c < 3; ++c) {
            const double expected = param.exact
                                        ? want[t][k][c]
                                        : static_cast<double>(static_cast<float>(want[t][k][c]));
            EXPECT_EQ(got[t][k][c], expected) << "triangle " << t << " corner " << k;
          }
        }
      }
    } else {
      expect_same_points(soup, original);
      EXPECT_EQ(soup.triangles, original.triangles);
    }
    if (param.regions) {
      EXPECT_EQ(soup.regions.size(), original.triangles.size());
      if (!original.regions.empty()) {
        EXPECT_EQ(soup.regions, original.regions);
      }
    } else {
      EXPECT_TRUE(soup.regions.empty());
    }

    const Mesh mesh = read_mesh(path);
    EXPECT_EQ(mesh.n_vertices(), original.points.size());
    EXPECT_EQ(mesh.n_faces(), original.triangles.size());
    EXPECT_EQ(count_new_faces(mesh), 0u);
    if (param.regions) {
      EXPECT_EQ(to_soup(mesh).regions, original.regions);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllFormats, RoundTripTest,
    ::testing::Values(RoundTrip{"Off", "mesh.off", true, true, false, false},
                      RoundTrip{"Obj", "mesh.obj", true, true, false, false},
                      RoundTrip{"StlAscii", "mesh.stl", false, true, true, false},
                      RoundTrip{"StlBinary", "mesh.stl", true, false, true, false},
                      RoundTrip{"PlyAscii", "mesh.ply", false, true, false, true},
                      RoundTrip{"PlyBinary", "mesh.PLY", true, true, false, true}),
    [](const ::testing::TestParamInfo<RoundTrip>& info) { return std::string(info.param.name); });

// Invariant: PLY written with write_regions = false has no region property.
TEST_F(MeshIoTest, PlyWithoutRegions) {
  const fs::path path = file("noregions.ply");
  WriteOptions options;
  options.write_regions = false;
  write_mesh(build_mesh(test::octahedron_with_regions()), path, options);
  const TriangleSoup soup = read_soup(path);
  EXPECT_EQ(soup.triangles.size(), 8u);
  EXPECT_TRUE(soup.regions.empty());
}

// Invariant: a binary STL written by holebench does not start with "solid" (so that readers
// that look at the first bytes take it as binary) and has 84 + 50 * triangles bytes.
TEST_F(MeshIoTest, BinaryStlLayout) {
  const fs::path path = file("layout.stl");
  write_mesh(build_mesh(test::tetrahedron_soup()), path);
  EXPECT_EQ(fs::file_size(path), 84u + 50u * 4u);
  std::ifstream in(path, std::ios::binary);
  std::string start(5, '\0');
  in.read(&start[0], 5);
  EXPECT_NE(start, "solid");
}

// Invariant: deleted faces are not written (the writer goes through to_soup).
TEST_F(MeshIoTest, WriterSkipsDeletedFaces) {
  Mesh mesh = build_mesh(test::octahedron_with_regions());
  mesh.delete_face(FaceHandle(3), false);
  const fs::path path = file("deleted.off");
  write_mesh(mesh, path);
  const TriangleSoup soup = read_soup(path);
  EXPECT_EQ(soup.points.size(), 6u);
  EXPECT_EQ(soup.triangles.size(), 7u);
}

// Invariant: a file that cannot be created is a std::runtime_error naming the path.
TEST_F(MeshIoTest, WriteToMissingDirectoryThrows) {
  const fs::path path = file("no/such/dir/mesh.off");
  try {
    write_mesh(build_mesh(test::tetrahedron_soup()), path);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

// Invariant: writing with an unknown extension names the extension.
TEST_F(MeshIoTest, WriteUnknownExtensionThrows) {
  EXPECT_THROW(write_mesh(build_mesh(test::tetrahedron_soup()), file("mesh.xyz")),
               InvalidInputError);
}

// ------------------------------------------------------------------ hand-written files

// Invariant: OFF comments, counts and colour fields are handled; a quad becomes the fan
// (a b c), (a c d); a closed cube of quads is a valid mesh with 12 triangles.
TEST_F(MeshIoTest, OffCubeOfQuads) {
  const fs::path path = write("cube.off",
                              "# a unit cube\n"
                              "OFF\n"
                              "\n"
                              "8 6 12  # vertices faces edges\n"
                              "0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                              "0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                              "4 0 3 2 1  255 0 0\n"  // a colour after the indices
                              "4 4 5 6 7\n"
                              "# a comment between faces\n"
                              "4 0 1 5 4\n"
                              "4 1 2 6 5\n"
                              "4 2 3 7 6\n"
                              "4 3 0 4 7 0.5 0.5 0.5 1\n");
  const TriangleSoup soup = read_soup(path);
  ASSERT_EQ(soup.points.size(), 8u);
  ASSERT_EQ(soup.triangles.size(), 12u);
  EXPECT_EQ(soup.triangles[0], (std::array<int, 3>{0, 3, 2}));
  EXPECT_EQ(soup.triangles[1], (std::array<int, 3>{0, 2, 1}));
  EXPECT_EQ(soup.points[6], Point(1, 1, 1));
  const Mesh mesh = read_mesh(path);
  EXPECT_EQ(mesh.n_faces(), 12u);
  EXPECT_EQ(mesh.n_edges(), 18u);
}

// Invariant: the counts may follow "OFF" on its line, or the header may be missing; CRLF
// line endings and leading '+' signs are accepted.
TEST_F(MeshIoTest, OffHeaderVariants) {
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  for (const std::string& content :
       {"OFF 4 4 6\n" + body, "4 4 6\n" + body, "COFF\n4 4 0\n" + body,
        std::string("OFF\r\n4 4 6\r\n+0 0 0\r\n1e0 0 0\r\n0 1.0 0\r\n0 0 1\r\n3 0 2 1\r\n"
                    "3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n")}) {
    const TriangleSoup soup = read_soup(write("t.off", content));
    expect_same_points(soup, test::tetrahedron_soup());
    EXPECT_EQ(soup.triangles, test::tetrahedron_soup().triangles);
  }
}

// Invariant: OBJ faces with i, i/j, i//k, i/j/k and negative (relative) indices give the
// same tetrahedron; w, vt, vn, g, o, s, usemtl and mtllib are ignored.
TEST_F(MeshIoTest, ObjIndexForms) {
  const fs::path path = write("tetra.obj",
                              "# tetrahedron\n"
                              "mtllib tetra.mtl\n"
                              "o tetra\n"
                              "v 0 0 0\n"
                              "v 1 0 0 1.0\n"
                              "v 0 1 0\n"
                              "v 0 0 1\n"
                              "vt 0 0\nvt 1 0\nvt 0 1\n"
                              "vn 0 0 1\n"
                              "g side\n"
                              "s off\n"
                              "usemtl red\n"
                              "f 1/1/1 3/3/1 2/2/1\n"
                              "f 1//1 2//1 4//1\n"
                              "f -4/1 -1/2 -2/3\n"
                              "f 2 3 4\n");
  const TriangleSoup soup = read_soup(path);
  expect_same_points(soup, test::tetrahedron_soup());
  EXPECT_EQ(soup.triangles, test::tetrahedron_soup().triangles);
  EXPECT_EQ(read_mesh(path).n_faces(), 4u);
}

// Invariant: OBJ polygons are fanned, and faces may name vertices defined later.
TEST_F(MeshIoTest, ObjQuadAndForwardReference) {
  const TriangleSoup soup =
      read_soup(write("quad.obj", "f 1 2 3 4\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"));
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
}

// Invariant: an ASCII STL (any keyword case, CRLF) becomes a connected mesh: the 12 corners
// of a tetrahedron merge into 4 vertices.
TEST_F(MeshIoTest, AsciiStlMergesCorners) {
  std::string text = "solid tetra\r\n";
  for (const auto& t : corners_of(test::tetrahedron_soup())) {
    text += "  FACET NORMAL 0 0 0\r\n    outer loop\r\n";
    for (const Point& p : t)
      text += fmt::format("      vertex {} {} {}\r\n", p[0], p[1], p[2]);
    text += "    endloop\r\n  endfacet\r\n";
  }
  text += "endsolid tetra\r\n";
  const fs::path path = write("tetra.stl", text);
  const TriangleSoup soup = read_soup(path);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.triangles.size(), 4u);
  EXPECT_EQ(corners_of(soup), corners_of(test::tetrahedron_soup()));
  EXPECT_EQ(read_mesh(path).n_edges(), 6u);
}

// Invariant: a binary STL whose header starts with "solid" is read as binary, because its
// size is exactly 84 + 50 * count.
TEST_F(MeshIoTest, BinaryStlStartingWithSolid) {
  const fs::path path =
      write("solid.stl", binary_stl("solid but binary", 4, corners_of(test::tetrahedron_soup())));
  const TriangleSoup soup = read_soup(path);
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.triangles.size(), 4u);
  EXPECT_EQ(corners_of(soup), corners_of(test::tetrahedron_soup()));
}

// Invariant: a big-endian PLY with mixed types, extra properties, an extra element and a
// skipped list property is decoded, with the face "region" property.
TEST_F(MeshIoTest, BigEndianPlyWithExtraProperties) {
  const bool be = true;
  Bytes bytes;
  bytes.text(
      "ply\n"
      "format binary_big_endian 1.0\n"
      "comment written by hand\n"
      "element vertex 4\n"
      "property float32 x\n"
      "property uchar red\n"
      "property float y\n"
      "property double z\n"
      "element edge 1\n"
      "property int vertex1\n"
      "property int16 vertex2\n"
      "element face 4\n"
      "property uint8 flags\n"
      "property list uchar uint vertex_indices\n"
      "property short region\n"
      "property list ushort int8 other\n"
      "end_header\n");
  const TriangleSoup tetra = test::tetrahedron_soup();
  for (const Point& p : tetra.points) {
    bytes.f32(static_cast<float>(p[0]), be).uint(200, 1).f32(static_cast<float>(p[1]), be);
    bytes.f64(p[2], be);
  }
  bytes.uint(0, 4, be).uint(1, 2, be);  // the edge
  for (int j = 0; j < 4; ++j) {
    bytes.uint(9, 1).uint(3, 1);
    for (int k = 0; k < 3; ++k)
      bytes.uint(static_cast<std::uint64_t>(tetra.triangles[j][k]), 4, be);
    bytes.uint(static_cast<std::uint64_t>(10 + j), 2, be);
    bytes.uint(2, 2, be).uint(0xff, 1).uint(0x7f, 1);  // "other": two int8 values
  }
  const TriangleSoup soup = read_soup(write("be.ply", bytes.str()));
  expect_same_points(soup, tetra);
  EXPECT_EQ(soup.triangles, tetra.triangles);
  EXPECT_EQ(soup.regions, (std::vector<int>{10, 11, 12, 13}));
}

// Invariant: a little-endian PLY with list count type ushort, signed index type, negative
// region ids and the face element before the vertex element.
TEST_F(MeshIoTest, LittleEndianPlyFaceElementFirst) {
  Bytes bytes;
  bytes.text(
      "ply\r\n"
      "format binary_little_endian 1.0\r\n"
      "element face 4\r\n"
      "property list ushort int16 vertex_index\r\n"
      "property int32 region\r\n"
      "element vertex 4\r\n"
      "property float64 x\r\n"
      "property float64 y\r\n"
      "property float64 z\r\n"
      "end_header\r\n");
  const TriangleSoup tetra = test::tetrahedron_soup();
  for (int j = 0; j < 4; ++j) {
    bytes.uint(3, 2);
    for (int k = 0; k < 3; ++k)
      bytes.uint(static_cast<std::uint64_t>(tetra.triangles[j][k]), 2);
    bytes.uint(static_cast<std::uint32_t>(-1 - j), 4);
  }
  for (const Point& p : tetra.points)
    bytes.f64(p[0]).f64(p[1]).f64(p[2]);
  const TriangleSoup soup = read_soup(write("le.ply", bytes.str()));
  expect_same_points(soup, tetra);
  EXPECT_EQ(soup.triangles, tetra.triangles);
  EXPECT_EQ(soup.regions, (std::vector<int>{-1, -2, -3, -4}));
}

// Invariant: an ASCII PLY with normals, an extra element and a quad (fanned) is read.
TEST_F(MeshIoTest, AsciiPlyWithQuad) {
  const TriangleSoup soup = read_soup(write("quad.ply",
                                            "ply\n"
                                            "format ascii 1.0\n"
                                            "element vertex 4\n"
                                            "property float x\n"
                                            "property float y\n"
                                            "property float z\n"
                                            "property float nx\n"
                                            "property float ny\n"
                                            "property float nz\n"
                                            "element face 1\n"
                                            "property list uchar int vertex_indices\n"
                                            "element material 2\n"
                                            "property list uchar float values\n"
                                            "end_header\n"
                                            "0 0 0 0 0 1\n"
                                            "1 0 0 0 0 1\n"
                                            "1 1 0 0 0 1\n"
                                            "0 1 0 0 0 1\n"
                                            "4 0 1 2 3\n"
                                            "2 0.5 0.25\n"
                                            "0\n"));
  EXPECT_EQ(soup.points.size(), 4u);
  EXPECT_EQ(soup.triangles, (std::vector<std::array<int, 3>>{{0, 1, 2}, {0, 2, 3}}));
  EXPECT_TRUE(soup.regions.empty());
}

// ------------------------------------------------------------------ bad input: any format

TEST_F(MeshIoTest, MissingFile) {
  expect_error(file("missing.off"), {"does not exist"});
}

TEST_F(MeshIoTest, Directory) {
  fs::create_directories(file("folder.off"));
  expect_error(file("folder.off"), {"directory"});
}

TEST_F(MeshIoTest, UnknownExtension) {
  expect_error(write("mesh.xyz", "OFF\n"), {"unknown mesh file extension", "'.xyz'"});
}

TEST_F(MeshIoTest, EmptyFileInEveryFormat) {
  for (const char* name : {"e.off", "e.obj", "e.stl", "e.ply"}) {
    expect_error(write(name, ""), {"empty"});
  }
}

TEST_F(MeshIoTest, RandomTextInEveryFormat) {
  const std::string text = "Hello world,\nthis is not a mesh.\n";
  expect_error(write("t.off", text), {"line 1", "not an OFF file"});
  expect_error(write("t.obj", text), {"not an OBJ mesh"});
  expect_error(write("t.ply", text), {"not a PLY file"});
  expect_error(write("t.stl", text), {"truncated", "not an ASCII STL"});
}

TEST_F(MeshIoTest, PngRenamedInEveryFormat) {
  const std::string png = png_bytes();
  expect_error(write("image.off", png), {"byte 8", "binary data", "not an OFF file"});
  expect_error(write("image.obj", png), {"binary data", "not an OBJ file"});
  expect_error(write("image.ply", png), {"not a PLY file"});
  expect_error(write("image.stl", png), {"byte", "binary STL header declares"});
}

// ------------------------------------------------------------------ bad input: OFF

const char* const kOffHead = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST_F(MeshIoTest, OffTruncatedVertices) {
  expect_error(write("t.off", "OFF\n8 6 0\n0 0 0\n1 0 0\n0 1 0\n"),
               {"truncated", "3 of 8 vertices"});
}

TEST_F(MeshIoTest, OffTruncatedFaces) {
  expect_error(write("t.off", std::string(kOffHead) + "3 0 2 1\n3 0 1 3\n"),
               {"line 8", "truncated", "2 of 4 faces"});
}

TEST_F(MeshIoTest, OffAbsurdCounts) {
  expect_error(write("t.off", "OFF\n1000000000000 1 0\n0 0 0\n1 0 0\n"),
               {"truncated", "2 of 1000000000000 vertices"});
  expect_error(write("t.off", "OFF\n3 1000000000000 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"),
               {"truncated", "1 of 1000000000000 faces"});
}

TEST_F(MeshIoTest, OffUnparsableNumber) {
  expect_error(write("t.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"),
               {"line 4", "cannot parse 'zero'", "vertex 1"});
  expect_error(write("t.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 two\n"),
               {"line 6", "cannot parse 'two'"});
  expect_error(write("t.off", "OFF\nthree 1 0\n"), {"line 2", "vertex and face counts"});
  expect_error(write("t.off", "OFF\n3 1 0\n0 0 1e999\n"), {"line 3", "out of the range"});
}

TEST_F(MeshIoTest, OffTooFewCoordinates) {
  expect_error(write("t.off", "OFF\n3 1 0\n0 0 0\n1 0\n"),
               {"line 4", "expected 3 coordinates", "vertex 1"});
}

TEST_F(MeshIoTest, OffNonFiniteCoordinates) {
  for (const char* bad : {"nan", "inf", "-Infinity"}) {
    const fs::path path =
        write("t.off", fmt::format("OFF\n3 1 0\n0 0 0\n1 {} 0\n0 1 0\n3 0 1 2\n", bad));
    EXPECT_TRUE(std::isnan(read_soup(path).points[1][1]) ||
                std::isinf(read_soup(path).points[1][1]));
    expect_error(path, {"vertex 1", "non-finite"}, /*whole_mesh=*/true);
  }
}

TEST_F(MeshIoTest, OffIndexOutOfRange) {
  expect_error(write("t.off", std::string(kOffHead) + "3 0 2 1\n3 0 1 7\n"),
               {"line 8", "face 1 references vertex 7", "4 vertices"});
  expect_error(write("t.off", std::string(kOffHead) + "3 0 -1 1\n"),
               {"line 7", "references vertex -1"});
}

TEST_F(MeshIoTest, OffFaceWithTooFewIndices) {
  expect_error(write("t.off", std::string(kOffHead) + "2 0 1\n"),
               {"line 7", "face 0 has 2 vertices", "at least 3"});
  expect_error(write("t.off", std::string(kOffHead) + "4 0 1 2\n"),
               {"line 7", "declares 4 vertices but lists 3"});
}

TEST_F(MeshIoTest, OffUnsupportedVariants) {
  expect_error(write("t.off", "4OFF\n1 0 0\n"), {"line 1", "unsupported OFF variant"});
  expect_error(write("t.off", "OFF BINARY\n"), {"line 1", "binary OFF"});
  expect_error(write("t.off", "# only a comment\n\n"), {"only blank lines and comments"});
}

// ------------------------------------------------------------------ bad input: OBJ

const char* const kObjHead = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n";

TEST_F(MeshIoTest, ObjBadVertices) {
  expect_error(write("t.obj", "v 0 0\n"), {"line 1", "expected 3 coordinates"});
  expect_error(write("t.obj", "# c\nv 0 x 0\n"), {"line 2", "cannot parse 'x'", "vertex 0"});
}

TEST_F(MeshIoTest, ObjBadFaces) {
  const std::string head = kObjHead;
  expect_error(write("t.obj", head + "f 1 2\n"), {"line 5", "at least 3 vertices"});
  expect_error(write("t.obj", head + "f 1 2 0\n"), {"line 5", "index 0"});
  expect_error(write("t.obj", head + "f 1 a 3\n"), {"line 5", "cannot parse face vertex 'a'"});
  expect_error(write("t.obj", head + "f 1 2 3\nf 1 2 9\nf 1 2 3\n"),
               {"line 6", "references vertex 9", "4 vertices"});
  expect_error(write("t.obj", head + "f -1 -2 -9\n"),
               {"line 5", "relative index -9", "4 vertices"});
}

// ------------------------------------------------------------------ bad input: STL

TEST_F(MeshIoTest, AsciiStlErrors) {
  const std::string facet =
      "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
      "endfacet\n";
  expect_error(write("t.stl", "solid x\n" + facet + "facet normal 0 0 1\nouter loop\nvertex 0"),
               {"line 11", "truncated", "inside facet 1"});
  expect_error(write("t.stl", "solid x\n" + facet), {"truncated", "before 'endsolid'"});
  expect_error(write("t.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertec 0 0 0\n"),
               {"line 4", "expected 'vertex' or 'endloop'", "'vertec'"});
  expect_error(write("t.stl",
                     "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"
                     "vertex 1 0 0\nendloop\nendfacet\nendsolid\n"),
               {"line 6", "facet 0 has 2 vertices"});
  expect_error(write("t.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 nan 0\n"),
               {"line 4", "non-finite"});
  expect_error(write("t.stl", "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0,5 0\n"),
               {"line 4", "cannot parse '0,5'"});
  expect_error(write("t.stl", "solid x\nfacet 0 0 1\n"), {"line 2", "expected 'normal'"});
  expect_error(write("t.stl", "solid x\nendsolid x\ngarbage\n"), {"line 3", "after 'endsolid'"});
}

TEST_F(MeshIoTest, BinaryStlTruncated) {
  const auto corners = corners_of(test::tetrahedron_soup());
  expect_error(write("t.stl", binary_stl("binary", 10, {corners[0]})),
               {"byte 134", "truncated", "declares 10 triangles", "after 1 of them"});
  expect_error(write("t.stl", binary_stl("binary", 4, corners).substr(0, 84 + 50 * 3 + 20)),
               {"byte 254", "truncated", "after 3 of them"});
  expect_error(write("t.stl", std::string(50, 'x')), {"byte 50", "truncated"});
}

TEST_F(MeshIoTest, BinaryStlAbsurdCount) {
  expect_error(
      write("t.stl", binary_stl("binary", 0xffffffffu, corners_of(test::tetrahedron_soup()))),
      {"truncated", "declares 4294967295 triangles"});
}

TEST_F(MeshIoTest, BinaryStlTrailingBytes) {
  expect_error(
      write("t.stl", binary_stl("binary", 1, corners_of(test::tetrahedron_soup())) + "junk"),
      {"byte 134", "not an STL file"});
}

TEST_F(MeshIoTest, BinaryStlNonFinite) {
  auto corners = corners_of(test::tetrahedron_soup());
  corners[1][2][0] = std::numeric_limits<double>::quiet_NaN();
  expect_error(write("t.stl", binary_stl("binary", 4, corners)),
               {"byte 170", "triangle 1", "non-finite"});
}

// ------------------------------------------------------------------ bad input: PLY

const char* const kPlyAsciiHead =
    "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    "property float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
const char* const kPlyAsciiVertices = "0 0 0\n1 0 0\n0 1 0\n0 0 1\n";

TEST_F(MeshIoTest, PlyHeaderErrors) {
  expect_error(write("t.ply", "ply\nformat ascii 1.0\nelement vertex 3\n"),
               {"truncated", "no 'end_header'"});
  expect_error(write("t.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float16 x\n"),
               {"line 4", "unknown property type 'float16'"});
  expect_error(write("t.ply", "ply\nformat binary_middle_endian 1.0\n"),
               {"line 2", "unknown PLY format"});
  expect_error(write("t.ply", "ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
               {"line 3", "'property' before any 'element'"});
  expect_error(write("t.ply", "ply\nformat ascii 1.0\nelement vertex -3\nend_header\n"),
               {"line 3", "element <name> <count>"});
  expect_error(write("t.ply",
                     "ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\n"
                     "property float z\nend_header\n0 0\n"),
               {"line 3", "no 'x' property"});
  expect_error(write("t.ply",
                     "ply\nformat ascii 1.0\nelement face 1\n"
                     "property list uchar int vertex_indices\nend_header\n3 0 1 2\n"),
               {"no 'vertex' element"});
  expect_error(write("t.ply", "ply\nelement vertex 0\nend_header\n"), {"no 'format' line"});
  expect_error(write("t.ply", "ply\nformat ascii 1.0\nvertices 3\nend_header\n"),
               {"line 3", "unexpected PLY header line"});
}

TEST_F(MeshIoTest, PlyAsciiErrors) {
  const std::string head = kPlyAsciiHead;
  expect_error(write("t.ply", head + "0 0 0\n1 0 0\n"),
               {"line 11", "truncated", "2 of 4 'vertex' elements"});
  expect_error(write("t.ply", head + kPlyAsciiVertices + "3 0 2 1\n"),
               {"line 14", "truncated", "1 of 4 'face' elements"});
  expect_error(write("t.ply", head + kPlyAsciiVertices + "3 0 2 4\n"),
               {"line 14", "face 0 references vertex 4", "4 vertices"});
  expect_error(write("t.ply", head + kPlyAsciiVertices + "2 0 2\n"),
               {"line 14", "face 0 has 2 vertices", "at least 3"});
  expect_error(write("t.ply", head + "0 0 0\n1 x 0\n"), {"line 11", "cannot parse 'x'"});
  expect_error(write("t.ply", head + "0 0 0\n1 0\n"), {"line 11", "too few values"});
  expect_error(write("t.ply", head + "0 0 0 7\n"), {"line 10", "more than the 3"});
  expect_error(write("t.ply", head + kPlyAsciiVertices + "3 0 2.5 1\n"),
               {"line 14", "cannot parse '2.5' as an integer"});
}

TEST_F(MeshIoTest, PlyAsciiNanReachesBuilder) {
  const fs::path path = write("t.ply", std::string(kPlyAsciiHead) +
                                           "0 0 0\n1 0 0\n0 nan 0\n0 0 1\n"
                                           "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  EXPECT_EQ(read_soup(path).triangles.size(), 4u);
  expect_error(path, {"vertex 2", "non-finite"}, /*whole_mesh=*/true);
}

std::string binary_ply_header(std::uint64_t vertices, std::uint64_t faces) {
  return fmt::format(
      "ply\nformat binary_little_endian 1.0\nelement vertex {}\nproperty double x\n"
      "property double y\nproperty double z\nelement face {}\n"
      "property list uchar int vertex_indices\nend_header\n",
      vertices, faces);
}

TEST_F(MeshIoTest, PlyBinaryTruncated) {
  const std::string head = binary_ply_header(4, 4);
  Bytes vertices;
  for (const Point& p : test::tetrahedron_soup().points)
    vertices.f64(p[0]).f64(p[1]).f64(p[2]);
  const std::size_t end = head.size() + 50;
  expect_error(write("t.ply", head + vertices.str().substr(0, 50)),
               {fmt::format("byte {}", end), "truncated", "2 of 4 'vertex' elements"});
  // Inside a face: the list says 3 indices, the file ends after 2.
  Bytes faces;
  faces.uint(3, 1).uint(0, 4).uint(2, 4).uint(1, 4).uint(3, 1).uint(0, 4).uint(1, 4);
  const std::string data = head + vertices.str() + faces.str();
  expect_error(write("t.ply", data),
               {fmt::format("byte {}", data.size()), "truncated", "inside 'face' element 1 of 4"});
}

TEST_F(MeshIoTest, PlyBinaryAbsurdCounts) {
  expect_error(write("t.ply", binary_ply_header(1000000000000, 1) + std::string(100, '\0')),
               {"truncated", "of 1000000000000 'vertex' elements"});
  Bytes faces;
  faces.uint(3, 1).uint(0, 4).uint(1, 4).uint(2, 4);
  Bytes vertices;
  for (const Point& p : test::tetrahedron_soup().points)
    vertices.f64(p[0]).f64(p[1]).f64(p[2]);
  expect_error(write("t.ply", binary_ply_header(4, 1000000000000) + vertices.str() + faces.str()),
               {"truncated", "inside 'face' element 1 of 1000000000000"});
  // A list that claims 255 indices with 12 bytes left.
  Bytes long_list;
  long_list.uint(255, 1).uint(0, 4).uint(1, 4).uint(2, 4);
  expect_error(write("t.ply", binary_ply_header(4, 1) + vertices.str() + long_list.str()),
               {"truncated", "inside 'face' element 0 of 1"});
}

TEST_F(MeshIoTest, PlyBinaryIndexOutOfRange) {
  const std::string head = binary_ply_header(4, 1);
  Bytes body;
  for (const Point& p : test::tetrahedron_soup().points)
    body.f64(p[0]).f64(p[1]).f64(p[2]);
  body.uint(3, 1).uint(0, 4).uint(1, 4).uint(static_cast<std::uint32_t>(-5), 4);
  const std::size_t offset = head.size() + 4 * 24 + 1 + 8;
  expect_error(write("t.ply", head + body.str()),
               {fmt::format("byte {}", offset), "face 0 references vertex -5"});
}

// ------------------------------------------------------------------ bad topology in files

TEST_F(MeshIoTest, ReadMeshReportsTopologyErrors) {
  const std::string five = "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n";
  expect_error(write("nm.off", five + "3 0 1 2\n3 1 0 3\n3 0 1 4\n"), {"non-manifold edge (0, 1)"},
               true);
  expect_error(write("orient.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n3 0 1 2\n3 0 1 3\n"),
               {"inconsistent orientation"}, true);
  expect_error(write("degen.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n"),
               {"degenerate triangle 0"}, true);
  expect_error(write("flat.obj", "v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n"),
               {"degenerate triangle 0", "zero area"}, true);
  expect_error(write("nmv.off", std::string(kOffHead).replace(4, 5, "6 5 0") +
                                    "-1 0 0\n-1 -1 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
                                    "3 0 4 5\n"),
               {"non-manifold vertex"}, true);
  expect_error(write("none.obj", "v 0 0 0\n"), {"no triangles"}, true);
}

}  // namespace
}  // namespace holebench
