#include "core/geometry.h"

#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench {
namespace {

TEST(Geometry, BoundingBoxDiagonalOfTheUnitTetrahedron) {
  const Mesh mesh = build_mesh(test::tetrahedron_soup());
  EXPECT_DOUBLE_EQ(bounding_box_diagonal(mesh), std::sqrt(3.0));
}

TEST(Geometry, FaceNormalAreaCentroid) {
  const Mesh mesh = build_mesh(test::grid_soup(1));
  const FaceHandle f = mesh.face_handle(0);
  const Point n = face_normal(mesh, f);
  EXPECT_DOUBLE_EQ(n[2], 1.0);
  EXPECT_DOUBLE_EQ(face_area(mesh, f), 0.5);
  EXPECT_DOUBLE_EQ(face_centroid(mesh, f)[0], 2.0 / 3.0);
}

// A roof: two squares folded along the x axis. Seen from above (normals up), the ridge
// is convex: angle +90 degrees; the same fold with normals down is reflex: -90 degrees.
TEST(Geometry, SignedDihedralAngleIsPositiveOnConvexAndNegativeOnReflexEdges) {
  TriangleSoup roof;
  roof.points = {Point(0, 0, 0),  Point(1, 0, 0),   Point(0, 1, -1),
                 Point(1, 1, -1), Point(0, -1, -1), Point(1, -1, -1)};
  roof.triangles = {{0, 1, 3}, {0, 3, 2}, {0, 4, 5}, {0, 5, 1}};
  for (bool flip : {false, true}) {
    TriangleSoup soup = roof;
    if (flip) {
      for (auto& t : soup.triangles)
        std::swap(t[1], t[2]);
    }
    const Mesh mesh = build_mesh(soup);
    int ridges = 0;
    for (auto e : mesh.edges()) {
      const Point a = mesh.point(e.v0());
      const Point b = mesh.point(e.v1());
      if (!(a[1] == 0 && b[1] == 0 && a[2] == 0 && b[2] == 0))
        continue;
      ++ridges;
      EXPECT_NEAR(signed_dihedral_angle(mesh, e), flip ? -M_PI / 2 : M_PI / 2, 1e-12);
    }
    EXPECT_EQ(ridges, 1);
  }
}

TEST(Geometry, FlatEdgesHaveZeroDihedralAngle) {
  const Mesh mesh = build_mesh(test::grid_soup(2));
  for (auto e : mesh.edges())
    EXPECT_NEAR(signed_dihedral_angle(mesh, e), 0.0, 1e-15);
}

}  // namespace
}  // namespace holebench
