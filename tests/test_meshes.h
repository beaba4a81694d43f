// Tiny meshes made in code, shared by the tests.
#pragma once

#include "core/mesh_builder.h"
#include "generators/box_solid.h"

#include <cmath>

namespace holebench::test {

/// A regular tetrahedron-like closed mesh, outward oriented.
inline TriangleSoup tetrahedron_soup() {
  TriangleSoup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
  soup.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return soup;
}

/// A closed octahedron whose coordinates have no short decimal form, with region ids.
inline TriangleSoup octahedron_with_regions() {
  const Point c(1.0 / 3.0, 2.0 / 7.0, -std::sqrt(2.0) * 1e-5);
  const double r = std::acos(-1.0) / 10.0;
  TriangleSoup soup;
  soup.points = {c + Point(r, 0, 0),  c + Point(-r, 0, 0), c + Point(0, r, 0),
                 c + Point(0, -r, 0), c + Point(0, 0, r),  c + Point(0, 0, -r)};
  soup.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  soup.regions = {0, 0, 1, 1, 2, 2, 3, 7};
  return soup;
}

/// An n x n grid of unit squares in the plane z = 0, two triangles each, normal +z.
/// Vertex (i, j) has index j * (n + 1) + i.
inline TriangleSoup grid_soup(int n) {
  TriangleSoup soup;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i)
      soup.points.emplace_back(i, j, 0.0);
  }
  auto index = [n](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      soup.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
      soup.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
    }
  }
  return soup;
}

/// The grid without the triangles of the cells listed (cell (i, j) = triangles 2(jn+i)
/// and 2(jn+i)+1).
inline TriangleSoup grid_without_cells(int n, const std::vector<std::pair<int, int>>& cells) {
  TriangleSoup full = grid_soup(n);
  std::vector<char> removed(full.triangles.size(), 0);
  for (auto [i, j] : cells) {
    removed[2 * (j * n + i)] = 1;
    removed[2 * (j * n + i) + 1] = 1;
  }
  TriangleSoup soup;
  soup.points = full.points;
  for (std::size_t t = 0; t < full.triangles.size(); ++t) {
    if (!removed[t])
      soup.triangles.push_back(full.triangles[t]);
  }
  return soup;
}

/// Every vertex moved by up to `amplitude` along a fixed pseudo-random direction that
/// depends on its index only (deterministic, no RNG library involved).
inline Mesh displaced(const Mesh& mesh, double amplitude) {
  Mesh out = mesh;
  for (auto v : out.vertices()) {
    const double phase = 0.7548776662 * v.idx();
    out.point(v) +=
        Point(std::sin(12.9898 * phase), std::sin(78.233 * phase), std::sin(37.719 * phase)) *
        amplitude;
  }
  return out;
}

/// A 2 x 1.5 x 1 box (cells of 0.25, regions 0..5 as make_box numbers them) whose top is split
/// at x = 1 into regions 5 (x > 1) and 6 (x < 1), as fusing bodies splits a face, the two
/// halves bent into a valley of `valley_degrees` (0: one plane).
inline Mesh box_with_split_top(double valley_degrees) {
  Mesh box = generators::make_box({Point(2.0, 1.5, 1.0), 0.25});
  for (auto f : box.faces()) {
    if (box.calc_face_centroid(f)[2] > 0.99 && box.calc_face_centroid(f)[0] < 1.0)
      set_region(box, f, 6);
  }
  const double slope = std::tan(0.5 * valley_degrees * M_PI / 180.0);
  for (auto v : box.vertices()) {
    Point p = box.point(v);
    if (p[2] > 0.99) {
      p[2] = 1.0 + slope * std::abs(p[0] - 1.0);
      box.set_point(v, p);
    }
  }
  return box;
}

}  // namespace holebench::test
