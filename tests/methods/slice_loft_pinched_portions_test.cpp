// Tests of methods/slice_loft/pinched_portions.h and the chord splits of the trimming: a
// portion whose boundary touches itself is trimmed as simple loops, and a facet never
// reuses an edge the mesh already has.
#include "methods/slice_loft/pinched_portions.h"

#include "tests/methods/slice_loft_papers_path.h"

#include <gtest/gtest.h>

#include <set>

namespace holebench {
namespace {

using slice_loft::BoundaryNode;

// Nodes standing for missing-feature points 0..n-1 (or, negative ids, vertices).
std::vector<BoundaryNode> nodes(const std::vector<int>& ids) {
  std::vector<BoundaryNode> out;
  for (int id : ids) {
    BoundaryNode node;
    if (id < 0)
      node.vertex = VertexHandle(-id);
    else
      node.feature = id;
    out.push_back(node);
  }
  return out;
}

std::vector<int> ids(const std::vector<BoundaryNode>& loop) {
  std::vector<int> out;
  for (const auto& node : loop)
    out.push_back(node.vertex.is_valid() ? -node.vertex.idx() : node.feature);
  return out;
}

TEST(SliceLoftPinchedPortions, SimpleLoopIsKept) {
  const auto loops = slice_loft::simple_boundary_loops(nodes({0, 1, 2, 3}));
  ASSERT_EQ(loops.size(), 1u);
  EXPECT_EQ(ids(loops[0]), (std::vector<int>{0, 1, 2, 3}));
}

// The boundary runs along the missing edge for one edge (D, E, D) at each end, as on a
// corner hole whose boundary follows a sharp edge: the spikes go, the quad stays.
TEST(SliceLoftPinchedPortions, SpikesAreCutOff) {
  // A B C D E D F B  (A = 0, B = 1, C = 2, D = 3, E = 4, F = 5)
  const auto loops = slice_loft::simple_boundary_loops(nodes({0, 1, 2, 3, 4, 3, 5, 1}));
  ASSERT_EQ(loops.size(), 1u);
  const std::vector<int> got = ids(loops[0]);
  EXPECT_EQ(std::set<int>(got.begin(), got.end()), (std::set<int>{1, 2, 3, 5}));
  EXPECT_EQ(got.size(), 4u);
}

// A figure eight through one node: two loops, each in the original direction.
TEST(SliceLoftPinchedPortions, PinchSplitsIntoTwoLoops) {
  const auto loops = slice_loft::simple_boundary_loops(nodes({0, 1, 2, 0, 3, 4}));
  ASSERT_EQ(loops.size(), 2u);
  EXPECT_EQ(ids(loops[0]), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(ids(loops[1]), (std::vector<int>{0, 3, 4}));
}

TEST(SliceLoftPinchedPortions, ZeroAreaLoopIsDropped) {
  EXPECT_TRUE(slice_loft::simple_boundary_loops(nodes({0, 1, 0})).empty());
  EXPECT_TRUE(slice_loft::simple_boundary_loops(nodes({0, 1, 2, 1})).empty());
}

TEST(SliceLoftPinchedPortions, FeaturePointOnAVertexBecomesTheVertex) {
  Mesh mesh;
  const VertexHandle a = mesh.add_vertex(Point(0, 0, 0));
  const VertexHandle b = mesh.add_vertex(Point(1, 0, 0));
  slice_loft::MissingFeatures features;
  features.points = {Point(1.0 + 1e-3, 0, 0), Point(0.5, 0.5, 0)};
  const auto on = slice_loft::feature_points_on_boundary(mesh, {a, b}, features, 0.1);
  ASSERT_EQ(on.size(), 2u);
  EXPECT_EQ(on[0], b);
  EXPECT_FALSE(on[1].is_valid());
  std::vector<BoundaryNode> loop = {{a, -1, mesh.point(a)},
                                    {VertexHandle(), 0, features.points[0]}};
  slice_loft::snap_feature_nodes(mesh, on, loop);
  EXPECT_EQ(loop[1].vertex, b);
  EXPECT_EQ(loop[1].position, mesh.point(b));
}

// The outer hole of a box with only its top kept: the hole's boundary is the top's outline,
// and the top's own triangulation already joins boundary vertices (near its corners) that a
// Delaunay triangulation of the same outline joins too. Those chords are split, so the hole
// is closed on the paper's path, and no edge gets a third face.
TEST(SliceLoftPinchedPortions, ChordsTheMeshHasAreSplit) {
  expect_closed_on_the_papers_path("brep/k1/outer/outer/small", "chords split",
                                   slice_loft::plus_options(false));
}

// A corner hole of the L-block whose boundary runs along two of its sharp edges: the rebuilt
// edges pass through boundary vertices, the portion is pinched, and the hole is still closed
// with its missing features.
TEST(SliceLoftPinchedPortions, CornerHoleAlongSharpEdgesIsClosedWithItsFeatures) {
  expect_closed_on_the_papers_path("solid/l_block/corner_ccr/small", "on the boundary");
}

}  // namespace
}  // namespace holebench
