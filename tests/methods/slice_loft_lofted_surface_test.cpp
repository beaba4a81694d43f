// Tests of methods/slice_loft/lofted_surface: the loft through section curves reproduces the
// surface they were cut from, is C2 across and along the sections, and its parameters invert
// its evaluation (trimming on the surface depends on that).
#include "methods/slice_loft/lofted_surface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace holebench::slice_loft {
namespace {

// Sections u = u0, u0 + du, ... of a surface given as a curve per u, sampled at `samples`
// parameter values in [t0, t1].
std::vector<SectionPolyline> sections_of(const std::function<Point(double, double)>& surface,
                                         int count, double u0, double du, double t0, double t1,
                                         int samples) {
  std::vector<SectionPolyline> sections;
  for (int k = 0; k < count; ++k) {
    SectionPolyline section;
    section.u = u0 + k * du;
    for (int i = 0; i < samples; ++i)
      section.points.push_back(surface(section.u, t0 + (t1 - t0) * i / (samples - 1)));
    sections.push_back(std::move(section));
  }
  return sections;
}

// A cylinder of radius r about the x axis, cut into exact 270-degree arcs (not a graph over
// any line in the section plane): the loft reproduces it within 1e-3 of the radius.
TEST(SliceLoftLoftedSurface, LoftThroughCylinderSectionsIsTheCylinder) {
  const double r = 1.0;
  auto cylinder = [&](double u, double angle) {
    return Point(u, r * std::cos(angle), r * std::sin(angle));
  };
  const auto sections = sections_of(cylinder, 12, 0.0, 0.2, -0.25 * M_PI, 1.25 * M_PI, 200);
  LoftOptions options;
  options.sample_spacing = 0.05;
  const LoftedSurface surface =
      LoftedSurface::loft(Point(0, 0, 0), Point(1, 0, 0), sections, options);
  ASSERT_TRUE(surface.ok()) << surface.error();
  const auto& s = surface.s_grid();
  double worst = 0.0;
  for (double u = 0.0; u <= 2.2; u += 0.037) {
    for (double t = s.front(); t <= s.back(); t += 0.031) {
      const Point p = surface.evaluate(u, t);
      EXPECT_NEAR(p[0], u, 1e-12);  // every surface point at u lies in the plane x = u
      worst = std::max(worst, std::abs(std::hypot(p[1], p[2]) - r));
    }
  }
  EXPECT_LT(worst, 1e-3 * r);
  // The parameters of a point on the cylinder lead back to it.
  for (double u = 0.1; u < 2.2; u += 0.3) {
    for (double angle = -0.2 * M_PI; angle < 1.2 * M_PI; angle += 0.4) {
      const Point p = cylinder(u, angle);
      const auto [pu, ps] = surface.parameters(p);
      EXPECT_NEAR(pu, u, 1e-12);
      EXPECT_LT((surface.evaluate(pu, ps) - p).norm(), 1e-3 * r);
    }
  }
}

// Second derivatives are continuous across the sections (u) and along them (s): second
// differences at a fine step change by no more than the step allows on either side of every
// section, though the data curve there (a bicubic spline is C2 at its knots).
TEST(SliceLoftLoftedSurface, CurvatureIsContinuousAcrossAndAlongSections) {
  auto bump = [](double u, double t) {
    return Point(u, t, 0.3 * std::sin(2.0 * t) * std::cos(1.5 * u) + 0.1 * u * u);
  };
  const auto sections = sections_of(bump, 9, 0.0, 0.25, -1.0, 1.0, 81);
  LoftOptions options;
  options.sample_spacing = 0.1;
  const LoftedSurface surface =
      LoftedSurface::loft(Point(0, 0, 0), Point(1, 0, 0), sections, options);
  ASSERT_TRUE(surface.ok()) << surface.error();
  const double h = 1e-3;
  auto second_u = [&](double u, double s) {
    return (surface.evaluate(u + h, s) - surface.evaluate(u, s) * 2.0 +
            surface.evaluate(u - h, s)) /
           (h * h);
  };
  auto second_s = [&](double u, double s) {
    return (surface.evaluate(u, s + h) - surface.evaluate(u, s) * 2.0 +
            surface.evaluate(u, s - h)) /
           (h * h);
  };
  for (double s : {-0.55, 0.0, 0.42}) {
    for (std::size_t k = 1; k + 1 < surface.section_u().size(); ++k) {
      const double knot = surface.section_u()[k];
      const Point before = second_u(knot - 2 * h, s), after = second_u(knot + 2 * h, s);
      EXPECT_LT((after - before).norm(), 0.05) << "across section " << k << " at s = " << s;
    }
  }
  const auto& grid = surface.s_grid();
  for (double u : {0.3, 1.1}) {
    for (std::size_t j = 2; j + 2 < grid.size(); j += 3) {
      const Point before = second_s(u, grid[j] - 2 * h), after = second_s(u, grid[j] + 2 * h);
      EXPECT_LT((after - before).norm(), 0.05) << "along s at " << grid[j] << ", u = " << u;
    }
  }
  // The test can fail: a piecewise-linear loft (the former height field across w) jumps.
  const Point kink = (surface.evaluate(0.5 + h, 0.0) - surface.evaluate(0.5, 0.0)) / h -
                     (surface.evaluate(0.5, 0.0) - surface.evaluate(0.5 - h, 0.0)) / h;
  EXPECT_LT(kink.norm(), 1e-2);
}

// The natural spline's weights reproduce linear data exactly: the reason a surface point at
// u lies in the section plane at u.
TEST(SliceLoftLoftedSurface, SplineWeightsReproduceLinearData) {
  const std::vector<double> x{0.0, 0.3, 0.7, 1.6, 2.0};
  for (double at : {-0.5, 0.1, 0.7, 1.234, 2.5}) {
    const auto w = NaturalCubicSpline::weights(x, at);
    double sum = 0.0, linear = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
      sum += w[i];
      linear += w[i] * x[i];
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_NEAR(linear, at, 1e-12);
  }
}

}  // namespace
}  // namespace holebench::slice_loft

namespace holebench::slice_loft {
namespace {

// A plane cut into sections of different extents: the map to (u, s) is affine, so collinear
// points (a feature line across the sections) stay collinear: trimming sees no false fold.
TEST(SliceLoftLoftedSurface, PlaneParametersAreAffine) {
  const Point d = Point(0.158811, -0.987309, 0).normalized();
  const Point e = OpenMesh::cross(Point(0, 0, -1), d);
  const Point origin(0.364, -0.0054, -0.1033);
  std::vector<SectionPolyline> sections;
  for (int k = 0; k < 14; ++k) {
    SectionPolyline section;
    section.u = -0.0426 + 0.00675 * k;
    const double lo = -0.03 - 0.004 * (k % 3), hi = 0.02 + 0.003 * (k % 4);
    for (double w = lo; w <= hi; w += 0.0031)
      section.points.push_back(origin + d * section.u + e * w);
    sections.push_back(std::move(section));
  }
  LoftOptions options;
  options.sample_spacing = 0.0039;
  const LoftedSurface surface = LoftedSurface::loft(origin, d, sections, options);
  ASSERT_TRUE(surface.ok());
  for (double y = -0.039; y < 0.03; y += 0.0041) {
    const Point p(0.375, y, -0.1033);
    const auto [u, s] = surface.parameters(p);
    EXPECT_NEAR(s, OpenMesh::dot(p - origin, e), 1e-12) << "y = " << y;
  }
}

}  // namespace
}  // namespace holebench::slice_loft
