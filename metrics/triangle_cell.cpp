#include "metrics/triangle_cell.h"

#include <algorithm>
#include <cstring>

namespace holebench {

std::size_t CellKeyHash::operator()(const CellKey& key) const {
  std::uint64_t h = 1469598103934665603ull;
  const auto mix = [&h](std::uint64_t word) {
    h ^= word;
    h *= 1099511628211ull;
  };
  for (std::uint64_t word : key.bits)
    mix(word);
  for (int face : key.faces)
    mix(static_cast<std::uint64_t>(static_cast<std::uint32_t>(face)));
  return static_cast<std::size_t>(h);
}

CellKey key_of(const TriangleCell& cell) {
  CellKey key;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k)
      std::memcpy(&key.bits[3 * i + k], &cell.corners[i][k], sizeof(double));
    std::memcpy(&key.bits[9 + i], &cell.corner_distance[i], sizeof(double));
  }
  key.faces = cell.corner_face;
  return key;
}

TriangleCell face_cell(const Mesh& a, FaceHandle f, const VertexDistances& vertices) {
  TriangleCell cell;
  int k = 0;
  for (auto v : a.fv_range(f)) {
    cell.corners[k] = a.point(v);
    cell.corner_distance[k] = vertices.distance[v.idx()];
    cell.corner_face[k] = vertices.nearest_face[v.idx()];
    ++k;
  }
  return cell;
}

double distance_bound_from_corners(const TriangleCell& cell, const Point& p) {
  const auto& c = cell.corners;
  const auto& d = cell.corner_distance;
  return std::min({d[0] + (p - c[0]).norm(), d[1] + (p - c[1]).norm(), d[2] + (p - c[2]).norm()});
}

EdgeMidpoints edge_midpoints(const TriangleCell& cell) {
  const auto& c = cell.corners;
  const auto& d = cell.corner_distance;
  EdgeMidpoints mid;
  mid.points = {(c[0] + c[1]) * 0.5, (c[1] + c[2]) * 0.5, (c[2] + c[0]) * 0.5};
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    mid.distance_bound[i] = std::min(d[i], d[j]) + 0.5 * (c[j] - c[i]).norm();
  }
  return mid;
}

std::array<TriangleCell, 4> midpoint_children(const TriangleCell& cell,
                                              const std::array<Point, 3>& midpoint,
                                              const std::array<double, 3>& midpoint_distance,
                                              const std::array<int, 3>& midpoint_face) {
  const auto& c = cell.corners;
  const auto& d = cell.corner_distance;
  const auto& f = cell.corner_face;
  const auto& m = midpoint;
  const auto& md = midpoint_distance;
  const auto& mf = midpoint_face;
  return {TriangleCell{{c[0], m[0], m[2]}, {d[0], md[0], md[2]}, {f[0], mf[0], mf[2]}},
          TriangleCell{{m[0], c[1], m[1]}, {md[0], d[1], md[1]}, {mf[0], f[1], mf[1]}},
          TriangleCell{{m[2], m[1], c[2]}, {md[2], md[1], d[2]}, {mf[2], mf[1], f[2]}},
          TriangleCell{{m[0], m[1], m[2]}, {md[0], md[1], md[2]}, {mf[0], mf[1], mf[2]}}};
}

}  // namespace holebench
