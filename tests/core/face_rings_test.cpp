// The faces within rings of a set of vertices, against an independent definition: on a
// triangle mesh the vertices of the faces around a vertex are its neighbours along edges, so
// ring k holds the faces with a vertex at most k - 1 edges from a seed (a breadth-first walk
// over the edges).
#include "core/face_rings.h"

#include "core/mesh_builder.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <limits>
#include <vector>

namespace holebench {
namespace {

std::vector<char> faces_near_by_edges(const Mesh& mesh, const std::vector<VertexHandle>& seeds,
                                      int rings) {
  std::vector<int> hops(mesh.n_vertices(), std::numeric_limits<int>::max());
  std::deque<VertexHandle> queue;
  for (VertexHandle v : seeds) {
    hops[v.idx()] = 0;
    queue.push_back(v);
  }
  while (!queue.empty()) {
    const VertexHandle v = queue.front();
    queue.pop_front();
    for (auto w : mesh.vv_range(v)) {
      if (hops[w.idx()] > hops[v.idx()] + 1) {
        hops[w.idx()] = hops[v.idx()] + 1;
        queue.push_back(w);
      }
    }
  }
  std::vector<char> chosen(mesh.n_faces(), 0);
  for (auto f : mesh.faces()) {
    for (auto v : mesh.fv_range(f))
      chosen[f.idx()] = chosen[f.idx()] || hops[v.idx()] <= rings - 1;
  }
  return chosen;
}

TEST(FaceRings, RingKHoldsTheFacesWithinKMinusOneEdgesOfASeed) {
  const int n = 12;
  const Mesh grid = build_mesh(test::grid_soup(n));
  const VertexHandle centre(6 * (n + 1) + 6), corner(0), edge(3);
  for (const std::vector<VertexHandle>& seeds :
       {std::vector<VertexHandle>{centre}, std::vector<VertexHandle>{corner, edge, edge}}) {
    for (int rings = 0; rings <= 8; ++rings) {
      const std::vector<char> chosen = faces_within_rings(grid, seeds, rings);
      EXPECT_EQ(chosen, faces_near_by_edges(grid, seeds, rings)) << rings << " rings";
    }
  }
  // Ring 1 of an inner vertex of the grid is its fan, and no rings choose nothing.
  const std::vector<char> fan = faces_within_rings(grid, {centre}, 1);
  std::size_t in_fan = 0;
  for (auto f : grid.vf_range(centre))
    in_fan += fan[f.idx()] ? 1 : 0;
  EXPECT_EQ(std::count(fan.begin(), fan.end(), 1), static_cast<std::ptrdiff_t>(in_fan));
  EXPECT_EQ(in_fan, 6u);
  const std::vector<char> none = faces_within_rings(grid, {centre}, 0);
  EXPECT_EQ(std::count(none.begin(), none.end(), 1), 0);
  // Enough rings reach every face.
  const std::vector<char> all = faces_within_rings(grid, {corner}, 2 * n + 1);
  EXPECT_EQ(std::count(all.begin(), all.end(), 1), static_cast<std::ptrdiff_t>(grid.n_faces()));
}

}  // namespace
}  // namespace holebench
