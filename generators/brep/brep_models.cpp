#include "generators/brep/brep_models.h"
#include "core/portable_math.h"  // the same bits on every machine

#include "generators/brep/voxel_solid.h"

#include <cmath>
#include <vector>

namespace holebench::generators::brep {
namespace {

// ---- three thin frames through a corner (the inner-inner-inner k = 3 holes) ------------

/// Cells of the frame models are given relative to the corner V; the voxel grid puts V at
/// (kFramesOrigin, ...) and the polyhedron is moved back so that V = (0, 0, 0).
constexpr int kFramesOrigin = 13;

/// A rectangle [u0, u1) x [v0, v1) of cells in a plane through V normal to an axis, in the
/// plane's cyclic coordinates (u, v): (y, z) for x, (z, x) for y, (x, y) for z.
struct CellRect {
  int u0, u1, v0, v1;
};

/// A plate one cell thick on the negative (`side` < 0) or positive side of the plane through
/// V normal to `axis`, covering `rects`.
void fill_plate(VoxelSolid& solid, int axis, int side, const std::vector<CellRect>& rects) {
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  for (const CellRect& r : rects) {
    CellIndex lo{}, hi{};
    lo[axis] = kFramesOrigin + (side < 0 ? -1 : 0);
    hi[axis] = lo[axis] + 1;
    lo[u] = kFramesOrigin + r.u0;
    hi[u] = kFramesOrigin + r.u1;
    lo[v] = kFramesOrigin + r.v0;
    hi[v] = kFramesOrigin + r.v1;
    solid.fill(lo, hi);
  }
}

/// Fills the cells of [lo, hi) (relative to V).
void fill_cells(VoxelSolid& solid, CellIndex lo, CellIndex hi) {
  for (int a = 0; a < 3; ++a) {
    lo[a] += kFramesOrigin;
    hi[a] += kFramesOrigin;
  }
  solid.fill(lo, hi);
}

Polyhedron frames_polyhedron(const VoxelSolid& solid) {
  Polyhedron p = to_polyhedron(solid);
  const Point shift(kFramesOrigin, kFramesOrigin, kFramesOrigin);
  for (auto& face : p.faces) {
    for (auto& point : face.outer)
      point -= shift;
    for (auto& loop : face.inner) {
      for (auto& point : loop)
        point -= shift;
    }
  }
  return p;
}

}  // namespace

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

Polyhedron make_corner_frames_model(bool reflex) {
  // A in z = 0, coordinates (x, y): frame [-8, 12] x [-12, 8] around the window
  // [-6, 10] x [-10, 6]; the tongue [-4, 0]^2 hangs on the window's left side by the arm
  // [-6, -4] x [-4, -2]. B and C are the same frame turned about the diagonal x = y = z
  // ((x, y, z) -> (z, x, y) maps A onto B and B onto C). On the y axis A lies at [-12, -10],
  // [-4, 0] and [6, 8], B at [-8, -6], [-4, 0] and [10, 12]: they share only the tongue edge
  // [-4, 0], and each frame passes once through the other's window (likewise on the other
  // two axes).
  const std::vector<CellRect> frame = {{-8, 12, -12, -10}, {-8, 12, 6, 8}, {-8, -6, -10, 6},
                                       {10, 12, -10, 6},   {-4, 0, -4, 0}, {-6, -4, -4, -2}};
  VoxelSolid solid({26, 26, 26});
  const int side = reflex ? +1 : -1;
  for (int axis = 0; axis < 3; ++axis)
    fill_plate(solid, axis, side, frame);
  if (reflex) {
    // In front of the faces the plates meet only along the tongues' edges: fill the
    // quarter between them along each edge and the cell at V.
    fill_cells(solid, {0, -4, 0}, {1, 0, 1});
    fill_cells(solid, {0, 0, -4}, {1, 1, 0});
    fill_cells(solid, {-4, 0, 0}, {0, 1, 1});
    fill_cells(solid, {0, 0, 0}, {1, 1, 1});
  }
  return frames_polyhedron(solid);
}

Polyhedron make_notch_frames_model(bool reflex) {
  // A in z = 0, (x, y): frame [-8, 8]^2 around the window [-6, 6]^2; the L-shaped tongue
  // [-4, 0] x [-4, 4] + [-4, 4] x [-4, 0] hangs on the window's left side by the arm
  // [-6, -4] x [-4, -2]. On both axes A lies at [-8, -6], [-4, 4] and [6, 8].
  const std::vector<CellRect> a = {{-8, 8, -8, -6}, {-8, 8, 6, 8},  {-8, -6, -6, 6}, {6, 8, -6, 6},
                                   {-4, 0, -4, 4},  {-4, 4, -4, 0}, {-6, -4, -4, -2}};
  // B in x = 0, (y, z): frame [-12, 12] x [-8, 6] around [-10, 10] x [-6, 4] (its sides cross
  // the y axis beyond A), the tongue [0, 4] x [-4, 0] standing on the window's bottom by the
  // arm [2, 4] x [-6, -4]. On the z axis B lies at [-8, -6], [-4, 0] and [4, 6].
  const std::vector<CellRect> b = {{-12, 12, -8, -6}, {-12, 12, 4, 6}, {-12, -10, -6, 4},
                                   {10, 12, -6, 4},   {0, 4, -4, 0},   {2, 4, -6, -4}};
  // C in y = 0, (z, x): frame z in [-12, 10], x in [-12, 12] around z in [-10, 8], x in
  // [-10, 10], the tongue z in [-4, 0], x in [0, 4] on the arm z in [-10, -4], x in [2, 4].
  // On the z axis C lies at [-12, -10], [-4, 0] and [8, 10], clear of B.
  const std::vector<CellRect> c = {{-12, -10, -12, 12}, {8, 10, -12, 12}, {-10, 8, -12, -10},
                                   {-10, 8, 10, 12},    {-4, 0, 0, 4},    {-10, -4, 2, 4}};
  VoxelSolid solid({26, 26, 26});
  const int side = reflex ? +1 : -1;
  fill_plate(solid, 2, side, a);
  fill_plate(solid, 0, side, b);
  fill_plate(solid, 1, side, c);
  // Fill the quarter between two plates along each tongue edge that is reflex.
  if (reflex) {
    fill_cells(solid, {0, 0, 0}, {1, 4, 1});  // A-B
    fill_cells(solid, {0, 0, 0}, {4, 1, 1});  // A-C
  } else {
    fill_cells(solid, {-1, -1, -4}, {0, 0, 0});  // B-C
  }
  return frames_polyhedron(solid);
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
  std::vector<Point> base;
  for (int i = 0; i < sides; ++i) {
    const double angle = 2.0 * kPi * i / sides;
    base.emplace_back(radius * portable_cos(angle), radius * portable_sin(angle), 0.0);
  }
  const Point apex(0.0, 0.0, height);
  Polyhedron p;
  for (int i = 0; i < sides; ++i)
    p.faces.push_back({{base[i], base[(i + 1) % sides], apex}, {}});
  p.faces.push_back({{base.rbegin(), base.rend()}, {}});
  return p;
}

}  // namespace holebench::generators::brep
