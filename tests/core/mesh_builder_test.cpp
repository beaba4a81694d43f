// build_mesh and to_soup: good soups become meshes with the same vertices, faces and
// regions; every kind of bad soup is an InvalidInputError naming the source and element.
#include "core/mesh_builder.h"
#include "core/errors.h"
#include "core/mesh.h"

#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <initializer_list>
#include <limits>
#include <string>

namespace holebench {
namespace {

/// Runs `f`, which must throw InvalidInputError; returns its message.
std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InvalidInputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected InvalidInputError, got another exception: " << e.what();
    return {};
  }
  ADD_FAILURE() << "expected InvalidInputError, nothing was thrown";
  return {};
}

/// build_mesh(soup) must fail with a message that starts with the source name and contains
/// every one of `parts`.
void expect_build_error(const TriangleSoup& soup, std::initializer_list<const char*> parts) {
  BuildOptions options;
  options.source = "shape.off";
  const std::string message = error_of([&] { build_mesh(soup, options); });
  EXPECT_EQ(message.rfind("shape.off: ", 0), 0u) << message;
  for (const char* part : parts) {
    EXPECT_NE(message.find(part), std::string::npos) << "missing '" << part << "' in: " << message;
  }
}

void expect_same_soup(const TriangleSoup& a, const TriangleSoup& b) {
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(a.points[i][c], b.points[i][c]) << "vertex " << i;
  }
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.regions, b.regions);
}

// Invariant: vertex i of the soup is vertex i of the mesh, triangle j is face j with the
// same corners in the same order, and every element is marked Original.
TEST(BuildMesh, KeepsVerticesFacesAndOrder) {
  const TriangleSoup soup = test::tetrahedron_soup();
  const Mesh mesh = build_mesh(soup);
  ASSERT_EQ(mesh.n_vertices(), 4u);
  ASSERT_EQ(mesh.n_faces(), 4u);
  for (auto v : mesh.vertices()) {
    EXPECT_EQ(mesh.point(v), soup.points[v.idx()]);
    EXPECT_EQ(provenance(mesh, v), Provenance::Original);
  }
  for (auto f : mesh.faces()) {
    std::array<int, 3> corners{};
    int k = 0;
    for (auto v : f.vertices())
      corners[k++] = v.idx();
    EXPECT_EQ(corners, soup.triangles[f.idx()]);
    EXPECT_EQ(provenance(mesh, f), Provenance::Original);
    EXPECT_EQ(region(mesh, f), kNoRegion);  // no regions in the soup
  }
  EXPECT_EQ(count_new_faces(mesh), 0u);
  EXPECT_EQ(region_count(mesh), 0);
}

// Invariant: face j gets region id regions[j].
TEST(BuildMesh, CopiesRegions) {
  const TriangleSoup soup = test::octahedron_with_regions();
  const Mesh mesh = build_mesh(soup);
  ASSERT_EQ(mesh.n_faces(), soup.triangles.size());
  for (auto f : mesh.faces())
    EXPECT_EQ(region(mesh, f), soup.regions[f.idx()]);
  EXPECT_EQ(region_count(mesh), 8);
}

// Invariant: with mark_original = false every element keeps the default provenance New.
TEST(BuildMesh, MarkOriginalFalseLeavesElementsNew) {
  BuildOptions options;
  options.mark_original = false;
  const Mesh mesh = build_mesh(test::tetrahedron_soup(), options);
  for (auto v : mesh.vertices())
    EXPECT_TRUE(is_new(mesh, v));
  EXPECT_EQ(count_new_faces(mesh), mesh.n_faces());
}

// Invariant: an open surface (boundary edges) is accepted; only topology errors are not.
TEST(BuildMesh, AcceptsOpenSurface) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Mesh mesh = build_mesh(soup);
  EXPECT_EQ(mesh.n_vertices(), 4u);
  EXPECT_EQ(mesh.n_faces(), 2u);
}

// Invariant: to_soup is the inverse of build_mesh (points, triangles and regions equal).
TEST(ToSoup, InvertsBuildMesh) {
  for (const TriangleSoup& soup : {test::tetrahedron_soup(), test::octahedron_with_regions()}) {
    expect_same_soup(to_soup(build_mesh(soup)), soup);
  }
}

// Invariant: to_soup skips deleted elements and compacts the vertex indices in handle order.
TEST(ToSoup, SkipsDeletedElements) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  soup.triangles = {{0, 1, 2}, {0, 2, 3}};
  soup.regions = {4, 5};
  Mesh mesh = build_mesh(soup);
  mesh.delete_face(FaceHandle(0), true);  // vertex 1 becomes isolated and is deleted too
  const TriangleSoup out = to_soup(mesh);
  TriangleSoup expected;
  expected.points = {Point(0, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};
  expected.triangles = {{0, 1, 2}};
  expected.regions = {5};
  expect_same_soup(out, expected);
}

// Each failure class of build_mesh: the message names the source and the element.

TEST(BuildMeshErrors, NoTriangles) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.triangles.clear();
  expect_build_error(soup, {"no triangles"});
}

TEST(BuildMeshErrors, NanCoordinate) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.points[2][1] = std::numeric_limits<double>::quiet_NaN();
  expect_build_error(soup, {"vertex 2", "non-finite"});
}

TEST(BuildMeshErrors, InfiniteCoordinate) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.points[3][0] = -std::numeric_limits<double>::infinity();
  expect_build_error(soup, {"vertex 3", "non-finite"});
}

TEST(BuildMeshErrors, IndexTooLarge) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.triangles[1][2] = 7;
  expect_build_error(soup, {"triangle 1", "references vertex 7", "4 vertices"});
}

TEST(BuildMeshErrors, NegativeIndex) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.triangles[3][0] = -1;
  expect_build_error(soup, {"triangle 3", "references vertex -1"});
}

TEST(BuildMeshErrors, RepeatedVertex) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.triangles[2] = {0, 3, 0};
  expect_build_error(soup, {"degenerate triangle 2", "repeats a vertex"});
}

TEST(BuildMeshErrors, ZeroArea) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 1, 1), Point(2, 2, 2)};  // collinear
  soup.triangles = {{0, 1, 2}};
  expect_build_error(soup, {"degenerate triangle 0", "zero area"});
}

TEST(BuildMeshErrors, NonManifoldEdge) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1)};
  soup.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // three triangles on edge (0, 1)
  expect_build_error(soup, {"non-manifold edge (0, 1)", "triangle 2"});
}

TEST(BuildMeshErrors, InconsistentOrientation) {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, -1, 0)};
  soup.triangles = {{0, 1, 2}, {0, 1, 3}};  // both run from 0 to 1
  expect_build_error(soup, {"inconsistent orientation", "triangles 0 and 1"});
}

TEST(BuildMeshErrors, NonManifoldVertex) {
  // A closed tetrahedron plus a triangle that touches it only at vertex 0.
  TriangleSoup soup = test::tetrahedron_soup();
  soup.points.push_back(Point(-1, 0, 0));
  soup.points.push_back(Point(-1, -1, 0));
  soup.triangles.push_back({0, 4, 5});
  expect_build_error(soup, {"non-manifold vertex", "triangle 4"});
}

TEST(BuildMeshErrors, RegionListOfWrongLength) {
  TriangleSoup soup = test::tetrahedron_soup();
  soup.regions = {0, 1};
  expect_build_error(soup, {"2 region ids for 4 triangles"});
}

}  // namespace
}  // namespace holebench
