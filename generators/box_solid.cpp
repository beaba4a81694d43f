#include "generators/box_solid.h"

#include "core/mesh_builder.h"

#include <array>
#include <cmath>
#include <map>
#include <tuple>

namespace holebench::generators {
namespace {

// Vertices are keyed by integer lattice coordinates, so that faces share their edges.
class LatticeVertices {
 public:
  LatticeVertices(TriangleSoup& soup, std::array<int, 3> cells, const Point& size)
      : soup_(soup), cells_(cells), size_(size) {}

  int at(std::array<int, 3> lattice) {
    const auto key = std::make_tuple(lattice[0], lattice[1], lattice[2]);
    auto it = index_.find(key);
    if (it != index_.end())
      return it->second;
    Point p;
    for (int a = 0; a < 3; ++a)
      p[a] = size_[a] * lattice[a] / cells_[a];
    soup_.points.push_back(p);
    const int index = static_cast<int>(soup_.points.size()) - 1;
    index_.emplace(key, index);
    return index;
  }

 private:
  TriangleSoup& soup_;
  std::array<int, 3> cells_;
  Point size_;
  std::map<std::tuple<int, int, int>, int> index_;
};

}  // namespace

Mesh make_box(const BoxOptions& options) {
  std::array<int, 3> cells{};
  for (int a = 0; a < 3; ++a) {
    cells[a] = std::max(1, static_cast<int>(std::ceil(options.size[a] / options.cell - 1e-9)));
  }
  TriangleSoup soup;
  LatticeVertices vertices(soup, cells, options.size);
  for (int axis = 0; axis < 3; ++axis) {
    // (axis, u, v) is a cyclic permutation, so e_u x e_v = e_axis.
    const int u = (axis + 1) % 3;
    const int v = (axis + 2) % 3;
    for (int side = 0; side < 2; ++side) {
      const int region_id = 2 * axis + side;
      for (int i = 0; i < cells[u]; ++i) {
        for (int j = 0; j < cells[v]; ++j) {
          auto corner = [&](int di, int dj) {
            std::array<int, 3> lattice{};
            lattice[axis] = side == 0 ? 0 : cells[axis];
            lattice[u] = i + di;
            lattice[v] = j + dj;
            return vertices.at(lattice);
          };
          // Counter-clockwise about +e_axis; reversed on the min side for outward normals.
          std::array<int, 4> quad{corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
          if (side == 0)
            std::swap(quad[1], quad[3]);
          // Alternate the diagonal so that the grid has no preferred direction.
          if ((i + j) % 2 == 0) {
            soup.triangles.push_back({quad[0], quad[1], quad[2]});
            soup.triangles.push_back({quad[0], quad[2], quad[3]});
          } else {
            soup.triangles.push_back({quad[0], quad[1], quad[3]});
            soup.triangles.push_back({quad[1], quad[2], quad[3]});
          }
          soup.regions.push_back(region_id);
          soup.regions.push_back(region_id);
        }
      }
    }
  }
  return build_mesh(soup, BuildOptions{"box generator"});
}

}  // namespace holebench::generators
