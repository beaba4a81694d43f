#include "generators/brep/voxel_solid.h"

#include <map>
#include <stdexcept>

namespace holebench::generators::brep {

VoxelSolid::VoxelSolid(CellIndex dims, double cell)
    : dims_(dims), cell_(cell), cells_(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2], 0) {}

VoxelSolid& VoxelSolid::fill(CellIndex lo, CellIndex hi) {
  for (int k = lo[2]; k < hi[2]; ++k) {
    for (int j = lo[1]; j < hi[1]; ++j) {
      for (int i = lo[0]; i < hi[0]; ++i) {
        if (i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] || k >= dims_[2])
          throw std::invalid_argument("VoxelSolid: box outside the grid");
        cells_[(static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i] = 1;
      }
    }
  }
  return *this;
}

VoxelSolid& VoxelSolid::carve(CellIndex lo, CellIndex hi) {
  for (int k = std::max(lo[2], 0); k < std::min(hi[2], dims_[2]); ++k) {
    for (int j = std::max(lo[1], 0); j < std::min(hi[1], dims_[1]); ++j) {
      for (int i = std::max(lo[0], 0); i < std::min(hi[0], dims_[0]); ++i)
        cells_[(static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i] = 0;
    }
  }
  return *this;
}

bool VoxelSolid::occupied(CellIndex c) const {
  for (int a = 0; a < 3; ++a) {
    if (c[a] < 0 || c[a] >= dims_[a])
      return false;
  }
  return cells_[(static_cast<std::size_t>(c[2]) * dims_[1] + c[1]) * dims_[0] + c[0]] != 0;
}

namespace {

using Corner = std::array<int, 2>;  // (u, v) lattice coordinates in a plane

// The cell sides of one plane with one outward normal, as a 2D occupancy grid.
struct SideGrid {
  int axis = 0;
  int side = 0;   // -1 or +1
  int plane = 0;  // coordinate along `axis`
  int width = 0, height = 0;
  std::vector<char> present;
  bool at(int p, int q) const {
    return p >= 0 && q >= 0 && p < width && q < height && present[q * width + p] != 0;
  }
};

Point to_point(const SideGrid& grid, Corner c, double cell) {
  Point p(0.0, 0.0, 0.0);
  p[grid.axis] = grid.plane * cell;
  p[(grid.axis + 1) % 3] = c[0] * cell;
  p[(grid.axis + 2) % 3] = c[1] * cell;
  return p;
}

// Signed area (doubled) of an integer loop.
long long signed_area2(const std::vector<Corner>& loop) {
  long long sum = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const auto& a = loop[i];
    const auto& b = loop[(i + 1) % loop.size()];
    sum += static_cast<long long>(a[0]) * b[1] - static_cast<long long>(b[0]) * a[1];
  }
  return sum;
}

void extract_faces(const SideGrid& grid, double cell, Polyhedron& polyhedron) {
  std::vector<int> component(grid.present.size(), -1);
  int count = 0;
  for (int q = 0; q < grid.height; ++q) {
    for (int p = 0; p < grid.width; ++p) {
      if (!grid.at(p, q) || component[q * grid.width + p] >= 0)
        continue;
      // Flood fill (4-connected) one face.
      std::vector<Corner> stack{{p, q}}, squares;
      component[q * grid.width + p] = count;
      while (!stack.empty()) {
        const Corner s = stack.back();
        stack.pop_back();
        squares.push_back(s);
        const Corner neighbours[4] = {
            {s[0] + 1, s[1]}, {s[0] - 1, s[1]}, {s[0], s[1] + 1}, {s[0], s[1] - 1}};
        for (const auto& n : neighbours) {
          if (grid.at(n[0], n[1]) && component[n[1] * grid.width + n[0]] < 0) {
            component[n[1] * grid.width + n[0]] = count;
            stack.push_back(n);
          }
        }
      }
      // Directed boundary edges, counter-clockwise about the outward normal: (u, v) is a
      // cyclic permutation after `axis`, so u x v = +e_axis; reversed on the - side.
      std::map<Corner, Corner> next;
      auto in_face = [&](int a, int b) {
        return grid.at(a, b) && component[b * grid.width + a] == count;
      };
      for (const auto& s : squares) {
        const Corner c[4] = {
            {s[0], s[1]}, {s[0] + 1, s[1]}, {s[0] + 1, s[1] + 1}, {s[0], s[1] + 1}};
        const Corner across[4] = {
            {s[0], s[1] - 1}, {s[0] + 1, s[1]}, {s[0], s[1] + 1}, {s[0] - 1, s[1]}};
        for (int e = 0; e < 4; ++e) {
          if (in_face(across[e][0], across[e][1]))
            continue;
          Corner from = c[e], to = c[(e + 1) % 4];
          if (grid.side < 0)
            std::swap(from, to);
          if (!next.emplace(from, to).second)
            throw std::invalid_argument("VoxelSolid: a face touches itself at a corner");
        }
      }
      PlanarFace face;
      bool have_outer = false;
      while (!next.empty()) {
        std::vector<Corner> loop;
        Corner start = next.begin()->first;
        for (Corner c = start;;) {
          loop.push_back(c);
          auto it = next.find(c);
          const Corner to = it->second;
          next.erase(it);
          if (to == start)
            break;
          c = to;
        }
        std::vector<Point> points;
        for (const auto& c : loop)
          points.push_back(to_point(grid, c, cell));
        // Counter-clockwise about the outward normal is the outer loop.
        const bool outer = (signed_area2(loop) > 0) == (grid.side > 0);
        if (outer) {
          if (have_outer)
            throw std::logic_error("VoxelSolid: a face with two outer loops");
          have_outer = true;
          face.outer = std::move(points);
        } else {
          face.inner.push_back(std::move(points));
        }
      }
      polyhedron.faces.push_back(std::move(face));
      ++count;
    }
  }
}

}  // namespace

Polyhedron to_polyhedron(const VoxelSolid& solid) {
  const CellIndex dims = solid.dims();
  // Edge-manifoldness: no two cells may share only an edge.
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int k = -1; k < dims[axis] + 1; ++k) {
      for (int i = -1; i < dims[u]; ++i) {
        for (int j = -1; j < dims[v]; ++j) {
          CellIndex c{};
          c[axis] = k;
          int pattern = 0;
          for (int b = 0; b < 4; ++b) {
            c[u] = i + (b & 1);
            c[v] = j + (b >> 1);
            pattern |= solid.occupied(c) ? (1 << b) : 0;
          }
          if (pattern == 0b1001 || pattern == 0b0110)
            throw std::invalid_argument("VoxelSolid: two cells touch only along an edge");
        }
      }
    }
  }
  Polyhedron polyhedron;
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (int side : {-1, +1}) {
      for (int plane = 0; plane <= dims[axis]; ++plane) {
        SideGrid grid;
        grid.axis = axis;
        grid.side = side;
        grid.plane = plane;
        grid.width = dims[u];
        grid.height = dims[v];
        grid.present.assign(static_cast<std::size_t>(grid.width) * grid.height, 0);
        bool any = false;
        for (int q = 0; q < grid.height; ++q) {
          for (int p = 0; p < grid.width; ++p) {
            CellIndex inside{}, outside{};
            inside[axis] = side > 0 ? plane - 1 : plane;
            outside[axis] = side > 0 ? plane : plane - 1;
            inside[u] = outside[u] = p;
            inside[v] = outside[v] = q;
            const bool boundary = solid.occupied(inside) && !solid.occupied(outside);
            grid.present[q * grid.width + p] = boundary ? 1 : 0;
            any = any || boundary;
          }
        }
        if (any)
          extract_faces(grid, solid.cell(), polyhedron);
      }
    }
  }
  return polyhedron;
}

}  // namespace holebench::generators::brep
