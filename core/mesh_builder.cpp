#include "core/mesh_builder.h"

#include "core/errors.h"

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <utility>

namespace holebench {
namespace {

[[noreturn]] void fail(const BuildOptions& options, const std::string& what) {
  throw InvalidInputError(fmt::format("{}: {}", options.source, what));
}

void check_points(const TriangleSoup& soup, const BuildOptions& options) {
  for (std::size_t i = 0; i < soup.points.size(); ++i) {
    const Point& p = soup.points[i];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      fail(options,
           fmt::format("vertex {} has a non-finite coordinate ({}, {}, {})", i, p[0], p[1], p[2]));
    }
  }
}

void check_triangles(const TriangleSoup& soup, const BuildOptions& options) {
  if (soup.triangles.empty())
    fail(options, "the mesh has no triangles");
  if (!soup.regions.empty() && soup.regions.size() != soup.triangles.size()) {
    fail(options,
         fmt::format("{} region ids for {} triangles", soup.regions.size(), soup.triangles.size()));
  }
  const auto n = static_cast<long long>(soup.points.size());
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& tri = soup.triangles[t];
    for (int index : tri) {
      if (index < 0 || index >= n) {
        fail(options, fmt::format("triangle {} references vertex {}, but there are {} vertices", t,
                                  index, n));
      }
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
      fail(options, fmt::format("degenerate triangle {}: it repeats a vertex ({} {} {})", t, tri[0],
                                tri[1], tri[2]));
    }
    const Point& a = soup.points[tri[0]];
    const Point& b = soup.points[tri[1]];
    const Point& c = soup.points[tri[2]];
    const double twice_area = OpenMesh::cross(b - a, c - a).norm();
    const double longest = std::max({(b - a).sqrnorm(), (c - b).sqrnorm(), (a - c).sqrnorm()});
    if (!(twice_area > 1e-14 * longest)) {
      fail(options, fmt::format("degenerate triangle {}: zero area (vertices {} {} {})", t, tri[0],
                                tri[1], tri[2]));
    }
  }
}

// Every directed edge may be used once; an undirected edge by at most two triangles,
// in opposite directions.
void check_edges(const TriangleSoup& soup, const BuildOptions& options) {
  std::map<std::pair<int, int>, std::size_t> directed;  // (from, to) -> triangle
  std::map<std::pair<int, int>, int> undirected;        // (min, max) -> use count
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& tri = soup.triangles[t];
    for (int e = 0; e < 3; ++e) {
      const int from = tri[e];
      const int to = tri[(e + 1) % 3];
      const auto key = std::minmax(from, to);
      if (++undirected[{key.first, key.second}] > 2) {
        fail(options, fmt::format("non-manifold edge ({}, {}): used by more than two triangles "
                                  "(the third is triangle {})",
                                  key.first, key.second, t));
      }
      const auto [it, inserted] = directed.emplace(std::make_pair(from, to), t);
      if (!inserted) {
        fail(options, fmt::format("inconsistent orientation: triangles {} and {} both run "
                                  "from vertex {} to vertex {}",
                                  it->second, t, from, to));
      }
    }
  }
}

}  // namespace

Mesh build_mesh(const TriangleSoup& soup, const BuildOptions& options) {
  check_points(soup, options);
  check_triangles(soup, options);
  check_edges(soup, options);

  Mesh mesh;
  std::vector<VertexHandle> vertices;
  vertices.reserve(soup.points.size());
  for (const Point& p : soup.points)
    vertices.push_back(mesh.add_vertex(p));
  for (std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& tri = soup.triangles[t];
    const FaceHandle f = mesh.add_face(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]);
    if (!f.is_valid()) {
      // Edges were checked above, so OpenMesh refused a non-manifold vertex.
      fail(options, fmt::format("non-manifold vertex: triangle {} ({} {} {}) would join two "
                                "separate fans of triangles at one vertex",
                                t, tri[0], tri[1], tri[2]));
    }
    if (!soup.regions.empty())
      set_region(mesh, f, soup.regions[t]);
  }
  if (options.mark_original)
    mark_all_original(mesh);
  return mesh;
}

TriangleSoup to_soup(const Mesh& mesh) {
  TriangleSoup soup;
  std::vector<int> index(mesh.n_vertices(), -1);
  for (auto v : mesh.vertices()) {
    index[v.idx()] = static_cast<int>(soup.points.size());
    soup.points.push_back(mesh.point(v));
  }
  bool any_region = false;
  for (auto f : mesh.faces()) {
    std::array<int, 3> tri{};
    int k = 0;
    for (auto v : f.vertices())
      tri[k++] = index[v.idx()];
    soup.triangles.push_back(tri);
    soup.regions.push_back(region(mesh, f));
    any_region = any_region || region(mesh, f) != kNoRegion;
  }
  if (!any_region)
    soup.regions.clear();
  return soup;
}

}  // namespace holebench
