#include "generators/brep/brep_models.h"

#include "generators/brep/voxel_solid.h"

#include <cmath>

namespace holebench::generators::brep {

Polyhedron make_box_model() {
  return to_polyhedron(VoxelSolid({6, 6, 6}).fill({0, 0, 0}, {6, 6, 6}));
}

Polyhedron make_corner_notch_model() {
  return to_polyhedron(
      VoxelSolid({10, 10, 10}).fill({0, 0, 0}, {10, 10, 10}).carve({5, 5, 5}, {10, 10, 10}));
}

Polyhedron make_block_on_plate_model() {
  return to_polyhedron(
      VoxelSolid({10, 10, 6}).fill({0, 0, 0}, {10, 10, 2}).fill({3, 3, 2}, {7, 7, 6}));
}

Polyhedron make_corner_block_model() {
  return to_polyhedron(
      VoxelSolid({10, 10, 9}).fill({0, 0, 0}, {10, 10, 5}).fill({0, 0, 5}, {4, 4, 9}));
}

Polyhedron make_valley_model() {
  return to_polyhedron(VoxelSolid({6, 6, 6}).fill({0, 0, 0}, {6, 6, 2}).fill({0, 0, 2}, {6, 2, 6}));
}

Polyhedron make_pocket_model() {
  return to_polyhedron(
      VoxelSolid({10, 10, 3}).fill({0, 0, 0}, {10, 10, 3}).carve({3, 3, 1}, {7, 7, 3}));
}

Polyhedron make_l_pocket_model() {
  return to_polyhedron(VoxelSolid({10, 10, 3})
                           .fill({0, 0, 0}, {10, 10, 3})
                           .carve({2, 2, 1}, {8, 5, 3})
                           .carve({2, 5, 1}, {5, 8, 3}));
}

Polyhedron make_l_boss_model() {
  return to_polyhedron(VoxelSolid({10, 10, 6})
                           .fill({0, 0, 0}, {10, 10, 2})
                           .fill({2, 2, 2}, {8, 5, 6})
                           .fill({2, 5, 2}, {5, 8, 6}));
}

Polyhedron make_tunnel_model() {
  return to_polyhedron(VoxelSolid({10, 10, 6})
                           .fill({0, 0, 0}, {10, 10, 3})
                           .carve({2, 1, 1}, {8, 4, 3})
                           .fill({2, 4, 3}, {8, 6, 6})
                           .carve({4, 4, 3}, {6, 6, 5}));
}

Polyhedron make_bridge_model() {
  return to_polyhedron(VoxelSolid({10, 10, 6})
                           .fill({0, 0, 0}, {10, 10, 3})
                           .carve({2, 1, 1}, {8, 4, 3})
                           .fill({2, 4, 3}, {8, 6, 6})
                           .fill({4, 1, 2}, {6, 4, 3}));
}

Polyhedron make_tunnel_rib_model() {
  return to_polyhedron(VoxelSolid({11, 10, 6})
                           .fill({0, 0, 0}, {11, 10, 3})
                           .carve({1, 1, 1}, {10, 5, 3})
                           .fill({2, 4, 1}, {9, 5, 6})
                           .carve({3, 4, 3}, {8, 5, 5})
                           .carve({5, 4, 2}, {8, 5, 3}));
}

Polyhedron make_beam_rib_model() {
  return to_polyhedron(VoxelSolid({11, 10, 6})
                           .fill({0, 0, 0}, {11, 10, 3})
                           .carve({2, 1, 1}, {9, 5, 3})
                           .fill({3, 4, 1}, {8, 5, 6})
                           .fill({4, 1, 2}, {6, 4, 3})
                           .fill({6, 1, 2}, {7, 4, 4}));
}

Polyhedron make_twisted_model() {
  return to_polyhedron(VoxelSolid({10, 10, 6})
                           .fill({0, 0, 0}, {10, 10, 3})
                           .fill({2, 4, 3}, {6, 7, 6})
                           .carve({4, 1, 1}, {8, 4, 3}));
}

Polyhedron make_step_model() {
  return to_polyhedron(
      VoxelSolid({10, 10, 6}).fill({0, 0, 0}, {10, 10, 3}).fill({0, 0, 3}, {10, 5, 6}));
}

Polyhedron make_triangular_prism_model() {
  const double side = 4.0, length = 8.0;
  // Counter-clockwise in (y, z), so counter-clockwise about +x.
  const double yz[3][2] = {{0.0, 0.0}, {side, 0.0}, {0.5 * side, 0.5 * std::sqrt(3.0) * side}};
  auto at = [&](double x, int i) { return Point(x, yz[i % 3][0], yz[i % 3][1]); };
  Polyhedron p;
  for (int i = 0; i < 3; ++i)
    p.faces.push_back({{at(0.0, i), at(0.0, i + 1), at(length, i + 1), at(length, i)}, {}});
  p.faces.push_back({{at(0.0, 2), at(0.0, 1), at(0.0, 0)}, {}});
  p.faces.push_back({{at(length, 0), at(length, 1), at(length, 2)}, {}});
  return p;
}

Polyhedron make_pyramid_model(int sides) {
  const double radius = 6.0, height = 6.0;
  const double pi = std::acos(-1.0);
  std::vector<Point> base;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * pi * i / sides;
    base.emplace_back(radius * std::cos(angle), radius * std::sin(angle), 0.0);
  }
  const Point apex(0.0, 0.0, height);
  Polyhedron p;
  for (int i = 0; i < sides; ++i)
    p.faces.push_back({{base[i], base[(i + 1) % sides], apex}, {}});
  p.faces.push_back({{base.rbegin(), base.rend()}, {}});
  return p;
}

}  // namespace holebench::generators::brep
