#include "generators/procedural_solids.h"
#include "core/portable_math.h"  // the same bits on every machine

#include "core/mesh_builder.h"
#include "core/region_segmentation.h"

#include <cmath>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

namespace holebench::generators {
namespace {

using Lattice = std::tuple<int, int, int>;

class LatticePoints {
 public:
  LatticePoints(TriangleSoup& soup, double step) : soup_(soup), step_(step) {}
  int at(int x, int y, int z) {
    const Lattice key{x, y, z};
    auto it = index_.find(key);
    if (it != index_.end())
      return it->second;
    soup_.points.emplace_back(x * step_, y * step_, z * step_);
    const int index = static_cast<int>(soup_.points.size()) - 1;
    index_.emplace(key, index);
    return index;
  }

 private:
  TriangleSoup& soup_;
  double step_;
  std::map<Lattice, int> index_;
};

Mesh segmented(const TriangleSoup& soup, const char* source) {
  Mesh mesh = build_mesh(soup, BuildOptions{source});
  assign_regions(mesh, segment_regions(mesh));
  return mesh;
}

}  // namespace

Mesh make_orthogonal_solid(const OrthogonalSolidOptions& options) {
  const std::set<Lattice> solid = [&] {
    std::set<Lattice> s;
    for (const auto& v : options.voxels)
      s.insert({v[0], v[1], v[2]});
    return s;
  }();
  const int n = options.subdivisions;
  TriangleSoup soup;
  LatticePoints points(soup, options.voxel_size / n);
  for (const auto& [x, y, z] : solid) {
    const int cell[3] = {x, y, z};
    for (int axis = 0; axis < 3; ++axis) {
      const int u = (axis + 1) % 3;
      const int v = (axis + 2) % 3;
      for (int side = 0; side < 2; ++side) {
        int neighbour[3] = {cell[0], cell[1], cell[2]};
        neighbour[axis] += side == 0 ? -1 : 1;
        if (solid.count({neighbour[0], neighbour[1], neighbour[2]}))
          continue;
        for (int i = 0; i < n; ++i) {
          for (int j = 0; j < n; ++j) {
            auto corner = [&](int di, int dj) {
              int l[3];
              l[axis] = (cell[axis] + side) * n;
              l[u] = cell[u] * n + i + di;
              l[v] = cell[v] * n + j + dj;
              return points.at(l[0], l[1], l[2]);
            };
            std::array<int, 4> q{corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
            if (side == 0)
              std::swap(q[1], q[3]);
            if ((i + j) % 2 == 0) {
              soup.triangles.push_back({q[0], q[1], q[2]});
              soup.triangles.push_back({q[0], q[2], q[3]});
            } else {
              soup.triangles.push_back({q[0], q[1], q[3]});
              soup.triangles.push_back({q[1], q[2], q[3]});
            }
          }
        }
      }
    }
  }
  return segmented(soup, "orthogonal solid generator");
}

namespace {

// Rings of a revolved solid: ring r has `segments` points at (radius_r, z_r); a radius of
// zero is a single point (a pole).
struct Ring {
  double radius;
  double z;
};

TriangleSoup revolve(const std::vector<Ring>& rings, int segments) {
  TriangleSoup soup;
  std::vector<int> first;  // index of each ring's first point
  for (const Ring& ring : rings) {
    first.push_back(static_cast<int>(soup.points.size()));
    if (ring.radius == 0.0) {
      soup.points.emplace_back(0.0, 0.0, ring.z);
      continue;
    }
    for (int s = 0; s < segments; ++s) {
      const double angle = 2.0 * kPi * s / segments;
      soup.points.emplace_back(ring.radius * portable_cos(angle), ring.radius * portable_sin(angle),
                               ring.z);
    }
  }
  // Consecutive rings are joined; the profile runs from the bottom pole to the top pole, so
  // that counter-clockwise triangles about the outward normal come out as written.
  for (std::size_t r = 0; r + 1 < rings.size(); ++r) {
    const bool pole_a = rings[r].radius == 0.0;
    const bool pole_b = rings[r + 1].radius == 0.0;
    for (int s = 0; s < segments; ++s) {
      const int s1 = (s + 1) % segments;
      const int a0 = first[r] + (pole_a ? 0 : s), a1 = first[r] + (pole_a ? 0 : s1);
      const int b0 = first[r + 1] + (pole_b ? 0 : s), b1 = first[r + 1] + (pole_b ? 0 : s1);
      if (!pole_a)
        soup.triangles.push_back({a0, a1, b1});
      if (!pole_b)
        soup.triangles.push_back({a0, b1, b0});
      if (pole_a && pole_b)
        throw std::invalid_argument("two consecutive poles");
    }
  }
  return soup;
}

void add_rings(std::vector<Ring>& rings, Ring from, Ring to, double spacing, bool include_last) {
  const double length = portable_hypot(to.radius - from.radius, to.z - from.z);
  const int steps = std::max(1, static_cast<int>(std::ceil(length / spacing - 1e-9)));
  for (int i = 1; i <= steps; ++i) {
    if (i == steps && !include_last)
      break;
    const double t = static_cast<double>(i) / steps;
    rings.push_back({from.radius + t * (to.radius - from.radius), from.z + t * (to.z - from.z)});
  }
}

}  // namespace

Mesh make_cylinder(const RevolvedSolidOptions& o) {
  std::vector<Ring> rings{{0.0, 0.0}};
  add_rings(rings, {0.0, 0.0}, {o.radius, 0.0}, o.spacing, true);
  add_rings(rings, {o.radius, 0.0}, {o.radius, o.height}, o.spacing, true);
  add_rings(rings, {o.radius, o.height}, {0.0, o.height}, o.spacing, true);
  return segmented(revolve(rings, o.segments), "cylinder generator");
}

Mesh make_cone(const RevolvedSolidOptions& o) {
  std::vector<Ring> rings{{0.0, 0.0}};
  add_rings(rings, {0.0, 0.0}, {o.radius, 0.0}, o.spacing, true);
  add_rings(rings, {o.radius, 0.0}, {0.0, o.height}, o.spacing, true);
  return segmented(revolve(rings, o.segments), "cone generator");
}

std::vector<std::string> procedural_solid_names() {
  return {"l_block", "stepped_block", "notched_block", "block_on_plate", "cylinder", "cone"};
}

Mesh make_procedural_solid(const std::string& name) {
  OrthogonalSolidOptions o;
  if (name == "l_block") {
    // An L extruded along y: reflex edge along y, corners ccc and ccr.
    o.voxels = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}, {0, 1, 0}, {1, 1, 0}, {0, 1, 1}};
  } else if (name == "stepped_block") {
    // Three steps: two reflex edges between treads and risers.
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 3; ++x) {
        for (int z = 0; z <= 2 - x; ++z)
          o.voxels.push_back({x, y, z});
      }
    }
  } else if (name == "notched_block") {
    // A 2x2x2 block without its (1,1,1) voxel: the notch's inner corner is rrr, the
    // corners where the notch meets the block are ccr.
    for (int x = 0; x < 2; ++x) {
      for (int y = 0; y < 2; ++y) {
        for (int z = 0; z < 2; ++z) {
          if (!(x == 1 && y == 1 && z == 1))
            o.voxels.push_back({x, y, z});
        }
      }
    }
  } else if (name == "block_on_plate") {
    // A 3x3x1 plate with one voxel on its middle: where the block's vertical edges meet the
    // plate, the corners are crr.
    for (int x = 0; x < 3; ++x) {
      for (int y = 0; y < 3; ++y)
        o.voxels.push_back({x, y, 0});
    }
    o.voxels.push_back({1, 1, 1});
  } else if (name == "cylinder") {
    return make_cylinder({});
  } else if (name == "cone") {
    return make_cone({});
  } else {
    throw std::invalid_argument("unknown procedural solid '" + name + "'");
  }
  return make_orthogonal_solid(o);
}

}  // namespace holebench::generators
