#include "generators/box_holes.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "core/region_segmentation.h"
#include "generators/case_catalog.h"

#include <gtest/gtest.h>

#include <set>

namespace holebench::generators {
namespace {

// The regions a hole's loop runs along, from the faces next to its boundary.
std::set<int> regions_along_loop(const Mesh& mesh, const BoundaryLoop& loop) {
  std::set<int> regions;
  for (auto h : loop.halfedges)
    regions.insert(region(mesh, mesh.opposite_face_handle(h)));
  return regions;
}

// Independent check of the labels: the regions around the loop give k, and the missing
// corner / edge lie where the removed faces were.
TEST(BoxHoles, LabelsMatchTheGeometryAroundTheHole) {
  for (auto target : {BoxHoleTarget::FaceInterior, BoxHoleTarget::Edge, BoxHoleTarget::Corner}) {
    SCOPED_TRACE(to_string(target));
    BoxHoleOptions options;
    options.target = target;
    const Case c = make_box_hole_case(options);
    ASSERT_EQ(c.holes.size(), 1u);
    const auto& truth = c.holes[0];
    ASSERT_TRUE(truth.labels.has_value());
    const auto loops = find_boundary_loops(c.input);
    ASSERT_EQ(loops.size(), 1u);
    EXPECT_EQ(static_cast<int>(regions_along_loop(c.input, loops[0]).size()), truth.labels->k);
    EXPECT_EQ(c.input.n_faces() + truth.removed_faces.size(), c.complete.n_faces());
    EXPECT_EQ(truth.labels->orientation, Orientation::Inner);
    // Every missing corner is a vertex of the complete model that the holed input lacks.
    for (const Point& corner : truth.missing_corners) {
      bool in_complete = false, in_input = false;
      for (auto v : c.complete.vertices())
        in_complete |= c.complete.point(v) == corner;
      for (auto v : c.input.vertices())
        in_input |= c.input.point(v) == corner;
      EXPECT_TRUE(in_complete);
      EXPECT_FALSE(in_input);
    }
    // A transition between two of the box's faces is convex: the sharp edges of the
    // complete model are all convex.
    for (auto e : c.complete.edges()) {
      EXPECT_GE(signed_dihedral_angle(c.complete, e), -1e-12);
    }
  }
}

TEST(BoxHoles, CaseIdAndSeedDetermineTheInputBitForBit) {
  const Case a = make_case("box/corner", 7);
  const Case b = make_case("box/corner", 7);
  ASSERT_EQ(a.input.n_vertices(), b.input.n_vertices());
  ASSERT_EQ(a.input.n_faces(), b.input.n_faces());
  for (auto v : a.input.vertices())
    EXPECT_EQ(a.input.point(v), b.input.point(b.input.vertex_handle(v.idx())));
  EXPECT_EQ(a.seed, 7u);
}

TEST(CaseCatalog, UnknownIdIsAnError) {
  EXPECT_THROW(make_case("no/such/case"), std::invalid_argument);
  std::size_t box_cases = 0;
  for (const auto& c : list_cases())
    box_cases += c.family == "box" ? 1 : 0;
  EXPECT_EQ(box_cases, 3u);
}

}  // namespace
}  // namespace holebench::generators
