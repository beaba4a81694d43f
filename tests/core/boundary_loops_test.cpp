#include "core/boundary_loops.h"

#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <set>

namespace holebench {
namespace {

// Invariant of every loop: consecutive halfedges are chained by `next`, each is a boundary
// halfedge, and every boundary halfedge of the mesh is in exactly one loop.
void expect_valid_loops(const Mesh& mesh, const std::vector<BoundaryLoop>& loops) {
  std::set<int> seen;
  for (const auto& loop : loops) {
    ASSERT_FALSE(loop.halfedges.empty());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const auto h = loop.halfedges[i];
      EXPECT_TRUE(mesh.is_boundary(h));
      EXPECT_EQ(mesh.next_halfedge_handle(h), loop.halfedges[(i + 1) % loop.size()]);
      EXPECT_TRUE(seen.insert(h.idx()).second) << "halfedge in two loops";
    }
  }
  std::size_t boundary = 0;
  for (auto h : mesh.halfedges())
    boundary += mesh.is_boundary(h) ? 1 : 0;
  EXPECT_EQ(seen.size(), boundary);
}

TEST(BoundaryLoops, ClosedMeshHasNone) {
  const Mesh mesh = build_mesh(test::tetrahedron_soup());
  EXPECT_TRUE(find_boundary_loops(mesh).empty());
}

TEST(BoundaryLoops, GridHasItsOuterBorderAsOneLoop) {
  const Mesh mesh = build_mesh(test::grid_soup(4));
  const auto loops = find_boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(loops[0].size(), 16u);  // 4 sides of 4 unit edges
  EXPECT_DOUBLE_EQ(loop_length(mesh, loops[0]), 16.0);
  expect_valid_loops(mesh, loops);
}

TEST(BoundaryLoops, OneHoleInsideTheGrid) {
  const Mesh mesh = build_mesh(test::grid_without_cells(5, {{2, 2}}));
  const auto loops = find_boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 2u);
  std::multiset<std::size_t> sizes{loops[0].size(), loops[1].size()};
  EXPECT_EQ(sizes, (std::multiset<std::size_t>{4u, 20u}));
  expect_valid_loops(mesh, loops);
}

TEST(BoundaryLoops, SeveralHoles) {
  const Mesh mesh = build_mesh(test::grid_without_cells(7, {{1, 1}, {1, 2}, {4, 4}, {5, 1}}));
  const auto loops = find_boundary_loops(mesh);
  // Outer border, a 1x2 hole (6 edges), two single cells (4 edges each).
  ASSERT_EQ(loops.size(), 4u);
  std::multiset<std::size_t> sizes;
  for (const auto& loop : loops)
    sizes.insert(loop.size());
  EXPECT_EQ(sizes, (std::multiset<std::size_t>{4u, 4u, 6u, 28u}));
  expect_valid_loops(mesh, loops);
}

TEST(BoundaryLoops, HoleWithAnIsland) {
  // A 3x3 ring of cells removed around the centre cell of a 7x7 grid: the centre cell
  // stays as an island, so the hole has an outer loop (12 edges) and the island's (4).
  std::vector<std::pair<int, int>> ring;
  for (int j = 2; j <= 4; ++j) {
    for (int i = 2; i <= 4; ++i) {
      if (!(i == 3 && j == 3))
        ring.emplace_back(i, j);
    }
  }
  const Mesh mesh = build_mesh(test::grid_without_cells(7, ring));
  const auto loops = find_boundary_loops(mesh);
  ASSERT_EQ(loops.size(), 3u);
  std::multiset<std::size_t> sizes;
  for (const auto& loop : loops)
    sizes.insert(loop.size());
  EXPECT_EQ(sizes, (std::multiset<std::size_t>{4u, 12u, 28u}));
  expect_valid_loops(mesh, loops);
}

TEST(BoundaryLoops, CentroidOfASquareHole) {
  const Mesh mesh = build_mesh(test::grid_without_cells(5, {{2, 2}}));
  for (const auto& loop : find_boundary_loops(mesh)) {
    if (loop.size() != 4)
      continue;
    const Point c = loop_centroid(mesh, loop);
    EXPECT_DOUBLE_EQ(c[0], 2.5);
    EXPECT_DOUBLE_EQ(c[1], 2.5);
    EXPECT_EQ(loop_vertices(mesh, loop).size(), 4u);
  }
}

}  // namespace
}  // namespace holebench
