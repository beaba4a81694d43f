#include "generators/missing_sharp_edges.h"

#include "core/features.h"
#include "core/geometry.h"
#include "generators/box_solid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace holebench::generators {
namespace {

using Polylines = std::vector<std::vector<Point>>;
using OnLine = std::function<bool(const Point&)>;

// The box [0,2] x [0,1.5] x [0,1] in cells of 0.5; regions 0..5 for -x, +x, -y, +y, -z, +z.
Mesh small_box() {
  BoxOptions options;
  options.cell = 0.5;
  return make_box(options);
}

FeatureAnalysis features_of(const Mesh& mesh) {
  FeatureOptions options;
  options.regions_from_mesh = true;
  return analyse_features(mesh, options);
}

bool near(double a, double b) {
  return std::abs(a - b) < 1e-12;
}

// The top edges along x (y = 1.5) and along y (x = 2), and the vertical one (x = 2, y = 1.5).
const OnLine kTopBackEdge = [](const Point& p) { return near(p[1], 1.5) && near(p[2], 1.0); };
const OnLine kTopRightEdge = [](const Point& p) { return near(p[0], 2.0) && near(p[2], 1.0); };
const OnLine kVerticalEdge = [](const Point& p) { return near(p[0], 2.0) && near(p[1], 1.5); };

// Removed: the two faces of every mesh edge with both ends on one of `lines`.
std::vector<char> faces_along(const Mesh& mesh, const std::vector<OnLine>& lines) {
  std::vector<char> removed(mesh.n_faces(), 0);
  for (auto e : mesh.edges()) {
    for (const auto& on : lines) {
      if (!on(mesh.point(e.v0())) || !on(mesh.point(e.v1())))
        continue;
      removed[e.h0().face().idx()] = 1;
      removed[e.h1().face().idx()] = 1;
    }
  }
  return removed;
}

std::vector<char> faces_of_region(const Mesh& mesh, int id) {
  std::vector<char> removed(mesh.n_faces(), 0);
  for (auto f : mesh.faces())
    removed[f.idx()] = region(mesh, f) == id ? 1 : 0;
  return removed;
}

// Whether `line` runs from a to b or from b to a.
bool joins(const std::vector<Point>& line, const Point& a, const Point& b) {
  return (line.front() == a && line.back() == b) || (line.front() == b && line.back() == a);
}

TEST(MissingSharpEdges, AWhollyRemovedEdgeIsOnePolylineEitherWay) {
  const Mesh box = small_box();
  const FeatureAnalysis features = features_of(box);
  const auto removed = faces_along(box, {kTopBackEdge});
  for (const Polylines& lines : {missing_sharp_edges(box, removed, RegionBorderEdges{}),
                                 missing_sharp_edges(box, removed, FeatureChainEdges{features})}) {
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].size(), 5u) << "four cells along x";
    EXPECT_TRUE(joins(lines[0], Point(0, 1.5, 1), Point(2, 1.5, 1)));
  }
}

TEST(MissingSharpEdges, NothingIsMissingWhereOneFaceIsKept) {
  const Mesh box = small_box();
  const FeatureAnalysis features = features_of(box);
  const auto removed = faces_of_region(box, 5);  // the top only: its sides keep their faces
  EXPECT_TRUE(missing_sharp_edges(box, removed, RegionBorderEdges{}).empty());
  EXPECT_TRUE(missing_sharp_edges(box, removed, FeatureChainEdges{features}).empty());
}

// Two missing edges meet at the corner (2, 1.5, 1), whose vertical edge is kept: chained
// among themselves they run on round the corner; along the feature chains they end there.
TEST(MissingSharpEdges, OnlyRegionBordersRunOnRoundACorner) {
  const Mesh box = small_box();
  const FeatureAnalysis features = features_of(box);
  const auto removed = faces_along(box, {kTopBackEdge, kTopRightEdge});
  for (auto e : box.edges()) {
    if (kVerticalEdge(box.point(e.v0())) && kVerticalEdge(box.point(e.v1()))) {
      ASSERT_FALSE(removed[e.h0().face().idx()] && removed[e.h1().face().idx()])
          << "the vertical edge is kept";
    }
  }
  const Point corner(2, 1.5, 1);

  const Polylines borders = missing_sharp_edges(box, removed, RegionBorderEdges{});
  ASSERT_EQ(borders.size(), 1u);
  EXPECT_EQ(borders[0].size(), 8u) << "four cells along x and three along y, one corner";
  EXPECT_TRUE(joins(borders[0], Point(0, 1.5, 1), Point(2, 0, 1)));

  const Polylines chains = missing_sharp_edges(box, removed, FeatureChainEdges{features});
  ASSERT_EQ(chains.size(), 2u);
  for (const auto& line : chains)
    EXPECT_TRUE(line.front() == corner || line.back() == corner);
}

// A border between two regions in one plane is sharp as a region border only: the feature
// analysis keeps the borders whose dihedral angle exceeds its threshold.
TEST(MissingSharpEdges, OnlyRegionBordersIncludeAFlatBorder) {
  Mesh box = small_box();
  for (auto f : box.faces()) {
    if (region(box, f) == 5 && face_centroid(box, f)[0] < 1.0)
      set_region(box, f, 6);
  }
  const FeatureAnalysis features = features_of(box);
  std::vector<char> removed(box.n_faces(), 0);
  for (auto f : box.faces())
    removed[f.idx()] = region(box, f) >= 5 ? 1 : 0;

  const Polylines borders = missing_sharp_edges(box, removed, RegionBorderEdges{});
  ASSERT_EQ(borders.size(), 1u);
  EXPECT_TRUE(joins(borders[0], Point(1, 0, 1), Point(1, 1.5, 1)));
  EXPECT_TRUE(missing_sharp_edges(box, removed, FeatureChainEdges{features}).empty());
}

}  // namespace
}  // namespace holebench::generators
