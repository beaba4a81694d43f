// Invariants of the guidance-arrow metric on scenes whose answer is known by construction:
// a camera looking straight into an unobstructed hole sees all of it (fraction 1); one
// behind a wall sees none (0); an arrow inside the model is not outside; a shaft through a
// wall is not free.
#include "metrics/embree/arrow_visibility.h"

#include "core/mesh_builder.h"
#include "generators/box_solid.h"
#include "metrics/embree/triangle_scene.h"
#include "tests/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

namespace holebench::embree {
namespace {

Mesh translated_grid(int n, double scale, const Point& offset) {
  TriangleSoup soup = test::grid_soup(n);
  for (auto& p : soup.points)
    p = p * scale + offset;
  return build_mesh(soup);
}

std::vector<int> all_faces(const Mesh& mesh) {
  std::vector<int> faces;
  for (auto f : mesh.faces())
    faces.push_back(f.idx());
  return faces;
}

// The missing surface: the unit square [0,1]^2 at z = 0, normal +z. A "holed model": a
// frame around it in the same plane (a 3x3 grid of unit cells without its middle cell,
// shifted so that the middle cell is the missing square).
struct Scene {
  Mesh missing = translated_grid(1, 1.0, Point(0, 0, 0));
  Mesh frame = build_mesh(test::grid_without_cells(3, {{1, 1}}));
  Scene() {
    for (auto v : frame.vertices())
      frame.point(v) -= Point(1, 1, 0);
  }
};

TEST(ArrowVisibility, CameraLookingStraightIntoAnUnobstructedHoleSeesAllOfIt) {
  Scene s;
  ArrowVisibilityOptions options;
  options.sample_spacing = 0.1;
  const auto samples = sample_faces(s.missing, all_faces(s.missing), options);
  // Each triangle: m = ceil(sqrt(2) / 0.1) = 15, so 15^2 sub-triangles.
  EXPECT_EQ(samples.points.size(), 2u * 15u * 15u);
  const TriangleScene holed(s.frame);
  // 3 above the centre: the square's corners are atan(0.707 / 3) = 13 degrees off axis.
  EXPECT_DOUBLE_EQ(visible_fraction(Point(0.5, 0.5, 3.0), Point(0, 0, -1), samples, holed), 1.0);
}

// The field of view is an option: a camera 0.5 above the square's centre with a 90-degree
// cone sees the disc of radius 0.5 inscribed in the square, pi / 4 of it (up to sampling);
// with the default 60 degrees, the disc of radius 0.5 tan(30) = 0.289: pi 0.289^2.
TEST(ArrowVisibility, TheFieldOfViewBoundsWhatIsSeen) {
  Scene s;
  ArrowVisibilityOptions options;
  options.sample_spacing = 0.01;
  const auto samples = sample_faces(s.missing, all_faces(s.missing), options);
  const TriangleScene holed(s.frame);
  const Point eye(0.5, 0.5, 0.5), down(0, 0, -1);
  options.field_of_view_degrees = 90.0;
  EXPECT_NEAR(visible_fraction(eye, down, samples, holed, options), M_PI / 4.0, 0.01);
  options.field_of_view_degrees = 60.0;
  const double r = 0.5 * std::tan(M_PI / 6.0);
  EXPECT_NEAR(visible_fraction(eye, down, samples, holed, options), M_PI * r * r, 0.01);
}

TEST(ArrowVisibility, CameraBehindAWallSeesNothing) {
  Scene s;
  // A wall: a 5x5 square at z = 1.5, between the camera and the hole.
  Mesh wall = translated_grid(5, 1.0, Point(-2, -2, 1.5));
  TriangleSoup both;
  for (const Mesh* m : {&s.frame, &wall}) {
    const int base = static_cast<int>(both.points.size());
    for (auto v : m->vertices())
      both.points.push_back(m->point(v));
    for (auto f : m->faces()) {
      std::array<int, 3> t;
      int k = 0;
      for (auto v : m->fv_range(f))
        t[k++] = base + v.idx();
      both.triangles.push_back(t);
    }
  }
  const TriangleScene holed(build_mesh(both));
  ArrowVisibilityOptions options;
  options.sample_spacing = 0.1;
  const auto samples = sample_faces(s.missing, all_faces(s.missing), options);
  EXPECT_EQ(visible_fraction(Point(0.5, 0.5, 3.0), Point(0, 0, -1), samples, holed), 0.0);
}

// From below, the square faces away from the camera: nothing is seen even without a wall.
TEST(ArrowVisibility, BackFacesAreNotSeen) {
  Scene s;
  const auto samples = sample_faces(s.missing, all_faces(s.missing), {});
  const TriangleScene holed(s.frame);
  EXPECT_EQ(visible_fraction(Point(0.5, 0.5, -3.0), Point(0, 0, 1), samples, holed), 0.0);
}

// The arrow quality on a box with a hole in its top: the complete box is the model.
TEST(ArrowVisibility, ArrowQualityOnABox) {
  const Mesh box = generators::make_box({Point(2.0, 2.0, 1.0), 0.25});
  // The top's faces within the square [0.75, 1.25]^2: the missing surface.
  std::vector<int> top;
  for (auto f : box.faces()) {
    Point c(0, 0, 0);
    for (auto v : box.fv_range(f))
      c += box.point(v) / 3.0;
    if (c[2] > 0.999 && c[0] > 0.75 && c[0] < 1.25 && c[1] > 0.75 && c[1] < 1.25)
      top.push_back(f.idx());
  }
  ASSERT_FALSE(top.empty());
  std::vector<char> removed(box.n_faces(), 0);
  for (int f : top)
    removed[f] = 1;
  TriangleSoup holed_soup;
  for (auto v : box.vertices())
    holed_soup.points.push_back(box.point(v));
  for (auto f : box.faces()) {
    if (removed[f.idx()])
      continue;
    std::array<int, 3> t;
    int k = 0;
    for (auto v : box.fv_range(f))
      t[k++] = v.idx();
    holed_soup.triangles.push_back(t);
  }
  const TriangleScene complete_scene(box);
  const TriangleScene holed_scene(build_mesh(holed_soup));
  ArrowVisibilityOptions options;
  options.sample_spacing = 0.05;
  options.search_directions = 1024;
  const auto samples = sample_faces(box, top, options);

  // Straight above, pointing down: outside, free, sees all, and no better direction.
  const auto good = arrow_quality({Point(1, 1, 3), Point(0, 0, -1)}, samples, complete_scene,
                                  holed_scene, options);
  EXPECT_TRUE(good.position_outside);
  EXPECT_TRUE(good.shaft_free);
  EXPECT_NEAR(good.shaft_length, 2.0, 1e-12);  // to the top face at z = 1
  EXPECT_DOUBLE_EQ(good.visible_fraction, 1.0);
  EXPECT_DOUBLE_EQ(good.best_visible_fraction, 1.0);
  EXPECT_EQ(good.direction_error_deg, 0.0);

  // Inside the box, pointing up at the hole: not outside; the missing surface faces away.
  const auto inside = arrow_quality({Point(1, 1, 0.5), Point(0, 0, 1)}, samples, complete_scene,
                                    holed_scene, options);
  EXPECT_FALSE(inside.position_outside);
  EXPECT_EQ(inside.visible_fraction, 0.0);

  // Below the box, pointing up: its shaft crosses the bottom face.
  const auto below = arrow_quality({Point(1, 1, -2), Point(0, 0, 1)}, samples, complete_scene,
                                   holed_scene, options);
  EXPECT_TRUE(below.position_outside);
  EXPECT_FALSE(below.shaft_free);

  // Above but looking sideways (90 degrees off): sees nothing; the best direction (straight
  // down, which sees everything) is 90 degrees away, up to the search's resolution.
  const auto sideways = arrow_quality({Point(1, 1, 3), Point(1, 0, 0)}, samples, complete_scene,
                                      holed_scene, options);
  EXPECT_EQ(sideways.visible_fraction, 0.0);
  EXPECT_DOUBLE_EQ(sideways.best_visible_fraction, 1.0);
  EXPECT_GT(sideways.direction_error_deg, 60.0);
  EXPECT_LE(sideways.direction_error_deg, 90.0);
}

}  // namespace
}  // namespace holebench::embree
