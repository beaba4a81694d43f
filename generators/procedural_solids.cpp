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

namespace {

// The point of the sweep at parameter t, radial offset rho and axial offset zeta.
Point helix_point(const HelicalSweepOptions& o, double t, double rho, double zeta) {
  return Point((o.radius + rho) * portable_cos(t), (o.radius + rho) * portable_sin(t),
               o.pitch * t / (2.0 * kPi) + zeta);
}

// Orients triangle `t` of `soup` so that its normal points away from `inside`.
void orient_away_from(TriangleSoup& soup, std::array<int, 3>& t, const Point& inside) {
  const Point& a = soup.points[t[0]];
  const Point normal = OpenMesh::cross(soup.points[t[1]] - a, soup.points[t[2]] - a);
  const Point centroid = (a + soup.points[t[1]] + soup.points[t[2]]) / 3.0;
  if (OpenMesh::dot(normal, centroid - inside) < 0.0)
    std::swap(t[1], t[2]);
}

}  // namespace

Mesh make_helical_sweep(const HelicalSweepOptions& o) {
  if (!(o.pitch > o.side) || !(o.radius > o.side) || o.steps < 4 || o.side_steps < 1)
    throw std::invalid_argument(
        "helical sweep: the turns would touch (pitch <= side) or the "
        "options are degenerate");
  const int m = o.side_steps;
  const double half = 0.5 * o.side;
  const double end = 2.0 * kPi * o.turns;
  TriangleSoup soup;
  // Rings of 4m points around the square, in the order bottom, outer, top, inner side.
  auto square_point = [&](int index) -> std::pair<double, double> {  // (rho, zeta)
    const int side = index / m, i = index % m;
    const double f = o.side * i / m;
    switch (side) {
      case 0:
        return {-half + f, -half};
      case 1:
        return {half, -half + f};
      case 2:
        return {half - f, half};
      default:
        return {-half, half - f};
    }
  };
  for (int k = 0; k <= o.steps; ++k) {
    const double t = end * k / o.steps;
    for (int index = 0; index < 4 * m; ++index) {
      const auto [rho, zeta] = square_point(index);
      soup.points.push_back(helix_point(o, t, rho, zeta));
    }
  }
  auto ring = [&](int k, int index) { return k * 4 * m + (index % (4 * m)); };
  for (int k = 0; k < o.steps; ++k) {
    const Point centre = helix_point(o, end * (k + 0.5) / o.steps, 0.0, 0.0);
    for (int index = 0; index < 4 * m; ++index) {
      std::array<int, 3> a{ring(k, index), ring(k, index + 1), ring(k + 1, index + 1)};
      std::array<int, 3> b{ring(k, index), ring(k + 1, index + 1), ring(k + 1, index)};
      orient_away_from(soup, a, centre);
      orient_away_from(soup, b, centre);
      soup.triangles.push_back(a);
      soup.triangles.push_back(b);
    }
  }
  // The two end caps: an (m + 1) x (m + 1) grid over the square, its border the ring's.
  for (int cap = 0; cap < 2; ++cap) {
    const int k = cap == 0 ? 0 : o.steps;
    const double t = end * k / o.steps;
    // Inside the solid, behind the cap.
    const Point inside = helix_point(o, cap == 0 ? t + 0.01 : t - 0.01, 0.0, 0.0);
    std::map<std::pair<int, int>, int> grid;
    for (int index = 0; index < 4 * m; ++index) {
      const auto [rho, zeta] = square_point(index);
      grid[{static_cast<int>(std::lround((rho + half) / o.side * m)),
            static_cast<int>(std::lround((zeta + half) / o.side * m))}] = ring(k, index);
    }
    for (int i = 1; i < m; ++i) {
      for (int j = 1; j < m; ++j) {
        grid[{i, j}] = static_cast<int>(soup.points.size());
        soup.points.push_back(helix_point(o, t, -half + o.side * i / m, -half + o.side * j / m));
      }
    }
    for (int i = 0; i < m; ++i) {
      for (int j = 0; j < m; ++j) {
        const int p00 = grid.at({i, j}), p10 = grid.at({i + 1, j});
        const int p01 = grid.at({i, j + 1}), p11 = grid.at({i + 1, j + 1});
        std::array<int, 3> a{p00, p10, p11}, b{p00, p11, p01};
        orient_away_from(soup, a, inside);
        orient_away_from(soup, b, inside);
        soup.triangles.push_back(a);
        soup.triangles.push_back(b);
      }
    }
  }
  return segmented(soup, "helical sweep generator");
}

std::vector<std::string> procedural_solid_names() {
  return {"l_block",  "stepped_block", "notched_block", "block_on_plate",
          "cylinder", "cone",          "helical_sweep"};
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
  } else if (name == "helical_sweep") {
    return make_helical_sweep({});
  } else {
    throw std::invalid_argument("unknown procedural solid '" + name + "'");
  }
  return make_orthogonal_solid(o);
}

}  // namespace holebench::generators
