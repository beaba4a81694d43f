#include "core/coplanar_regions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace holebench {
namespace {

// A strip of unit squares along x, each one region, its near edge (smaller x) at height z0
// and its far edge at z1, so that each square is planar and a bend is where z1 != z0.
struct StripSquare {
  int region;
  double z0, z1;  ///< heights of the near and far edges
};

Mesh strip(const std::vector<StripSquare>& squares) {
  Mesh mesh;
  for (std::size_t i = 0; i < squares.size(); ++i) {
    const double x = static_cast<double>(i);
    const auto a = mesh.add_vertex(Point(x, 0, squares[i].z0));
    const auto b = mesh.add_vertex(Point(x + 1, 0, squares[i].z1));
    const auto c = mesh.add_vertex(Point(x + 1, 1, squares[i].z1));
    const auto d = mesh.add_vertex(Point(x, 1, squares[i].z0));
    set_region(mesh, mesh.add_face(a, b, c), squares[i].region);
    set_region(mesh, mesh.add_face(a, c, d), squares[i].region);
  }
  // Weld the squares' shared edges: rebuild with vertices merged by position.
  Mesh welded;
  std::vector<std::pair<Point, VertexHandle>> seen;
  auto vertex_at = [&](const Point& p) -> VertexHandle {
    for (const auto& [q, v] : seen) {
      if ((q - p).norm() < 1e-12)
        return v;
    }
    const auto v = welded.add_vertex(p);
    seen.emplace_back(p, v);
    return v;
  };
  for (auto f : mesh.faces()) {
    std::vector<VertexHandle> corners;
    for (auto v : mesh.fv_range(f))
      corners.push_back(vertex_at(mesh.point(v)));
    set_region(welded, welded.add_face(corners), region(mesh, f));
  }
  return welded;
}

std::vector<int> groups_of(const Mesh& mesh) {
  const auto planes = fit_region_planes(mesh);
  std::vector<char> planar(planes.size());
  for (std::size_t r = 0; r < planes.size(); ++r)
    planar[r] = planes[r].valid && planes[r].plane.rms_residual < 1e-9;
  CoplanarRegionsOptions options;
  options.distance = 1e-9;
  return coplanar_region_groups(mesh, planes, planar, options);
}

// Three flat squares in regions 2, 0, 1 in a row are one face, named by its smallest id.
TEST(CoplanarRegions, FlatNeighboursAreOneGroupNamedByTheSmallestId) {
  const Mesh mesh = strip({{2, 0, 0}, {0, 0, 0}, {1, 0, 0}});
  EXPECT_EQ(groups_of(mesh), (std::vector<int>{0, 0, 0}));
}

// A bend of about 3 degrees (a draft) between two planar squares keeps them apart; the flat
// pair before it is one group.
TEST(CoplanarRegions, ABendOfAFewDegreesSeparatesTheFaces) {
  const double drop = std::tan(3.0 * M_PI / 180.0);
  const Mesh mesh = strip({{0, 0, 0}, {1, 0, 0}, {2, 0, -drop}});
  EXPECT_EQ(groups_of(mesh), (std::vector<int>{0, 0, 2}));
}

// Two parallel squares at different heights joined by a vertical one: parallel but not one
// plane, so three groups.
TEST(CoplanarRegions, ParallelFacesAtTwoHeightsStayApart) {
  Mesh mesh;
  const auto v = [&](double x, double y, double z) { return mesh.add_vertex(Point(x, y, z)); };
  const auto a0 = v(0, 0, 0), a1 = v(1, 0, 0), a2 = v(1, 1, 0), a3 = v(0, 1, 0);
  const auto b0 = v(1, 0, 1), b1 = v(1, 1, 1);
  const auto c0 = v(2, 0, 1), c1 = v(2, 1, 1);
  set_region(mesh, mesh.add_face(a0, a1, a2), 0);
  set_region(mesh, mesh.add_face(a0, a2, a3), 0);
  set_region(mesh, mesh.add_face(a1, b0, b1), 1);
  set_region(mesh, mesh.add_face(a1, b1, a2), 1);
  set_region(mesh, mesh.add_face(b0, c0, c1), 2);
  set_region(mesh, mesh.add_face(b0, c1, b1), 2);
  EXPECT_EQ(groups_of(mesh), (std::vector<int>{0, 1, 2}));
}

}  // namespace
}  // namespace holebench
