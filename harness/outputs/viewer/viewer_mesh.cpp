#include "harness/outputs/viewer/viewer_mesh.h"

#include "harness/outputs/file_names.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/heat_map.h"
#include "metrics/embree/triangle_scene.h"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <vector>

namespace holebench::viewer {
namespace {

std::string case_variant(const harness::Job& job) {
  return harness::file_stem_of_id(
      fmt::format("{}|{}|{}", job.case_id, job.noise_percent, job.seed));
}

/// What the PLY holds, before it is written.
struct ViewerPly {
  std::vector<std::array<float, 4>> vertices;  ///< x, y, z, quality
  std::vector<std::array<std::int32_t, 3>> faces;
  std::vector<std::uint8_t> patch;
  std::vector<std::array<std::int32_t, 2>> open_edges;  ///< the mesh's boundary edges
  double heat_scale_max_rel_diag = 0.0;                 ///< 0: not written
  std::optional<render::Camera> view;                   ///< written where set
};

template <typename T>
void put(std::string& out, T value) {
  static_assert(std::is_trivially_copyable_v<T>);
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // little-endian hosts only (x86-64, arm64)
  out.append(bytes, sizeof(T));
}

std::string encode(const ViewerPly& ply) {
  std::string out = "ply\nformat binary_little_endian 1.0\ncomment holebench viewer mesh\n";
  if (ply.heat_scale_max_rel_diag > 0.0)
    out += fmt::format("comment heat_scale_max_rel_diag {:.17g}\n", ply.heat_scale_max_rel_diag);
  if (const auto& view = ply.view) {
    const Point& d = view->direction;
    const Point& t = view->target;
    out += fmt::format("comment view_direction {:.9g} {:.9g} {:.9g}\n", d[0], d[1], d[2]);
    out += fmt::format("comment view_target {:.9g} {:.9g} {:.9g}\n", t[0], t[1], t[2]);
    out += fmt::format("comment view_distance {:.9g}\n", view->distance);
    out += fmt::format("comment view_field_of_view_degrees {:.9g}\n", view->field_of_view_degrees);
  }
  out += fmt::format(
      "element vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "property float quality\nelement face {}\nproperty list uchar int vertex_indices\n"
      "property uchar patch\nelement edge {}\nproperty int vertex1\nproperty int vertex2\n"
      "end_header\n",
      ply.vertices.size(), ply.faces.size(), ply.open_edges.size());
  for (const auto& v : ply.vertices) {
    for (float x : v)
      put(out, x);
  }
  for (std::size_t f = 0; f < ply.faces.size(); ++f) {
    put(out, static_cast<std::uint8_t>(3));
    for (std::int32_t i : ply.faces[f])
      put(out, i);
    put(out, ply.patch[f]);
  }
  for (const auto& edge : ply.open_edges) {
    put(out, edge[0]);
    put(out, edge[1]);
  }
  return out;
}

/// Writes under a temporary name, then renames: readers see the whole file or none.
void write_whole(const std::string& bytes, const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  const auto temporary = path.string() + fmt::format(".{}.tmp", ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << bytes;
    if (!out)
      throw std::runtime_error(path.string() + ": cannot write");
  }
  std::filesystem::rename(temporary, path);
}

std::array<float, 4> vertex(const Point& p, double quality) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]),
          static_cast<float>(quality)};
}

/// The kept faces with the mesh's own vertices (quality 0).
ViewerPly kept_faces(const Mesh& mesh, bool keep_new) {
  ViewerPly ply;
  for (auto v : mesh.vertices())
    ply.vertices.push_back(vertex(mesh.point(v), 0.0));
  for (auto f : mesh.faces()) {
    if (!keep_new && is_new(mesh, f))
      continue;
    std::array<std::int32_t, 3> face{};
    int i = 0;
    for (auto v : mesh.fv_range(f)) {
      if (i < 3)
        face[i] = v.idx();
      ++i;
    }
    ply.faces.push_back(face);
    ply.patch.push_back(0);
  }
  for (const auto& loop : find_boundary_loops(mesh)) {
    for (auto h : loop.halfedges) {
      ply.open_edges.push_back({mesh.from_vertex_handle(h).idx(), mesh.to_vertex_handle(h).idx()});
    }
  }
  return ply;
}

/// Splits the triangle (a, b, c) into n x n pieces, each vertex with its distance.
void add_split_face(ViewerPly& ply, const std::array<Point, 3>& corners, int n,
                    const embree::TriangleScene& truth, double diagonal) {
  const auto first = static_cast<std::int32_t>(ply.vertices.size());
  // Vertex (i, j) with i + j <= n at corners[0] + (i (b - a) + j (c - a)) / n.
  const auto index = [&](int i, int j) {
    // Rows of j: row j holds n - j + 1 vertices; those before it, sum over k < j.
    return first + j * (n + 1) - j * (j - 1) / 2 + i;
  };
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i + j <= n; ++i) {
      const Point p = corners[0] + ((corners[1] - corners[0]) * i + (corners[2] - corners[0]) * j) /
                                       static_cast<double>(n);
      ply.vertices.push_back(vertex(p, truth.closest_point(p).distance / diagonal));
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i + j < n; ++i) {
      ply.faces.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
      ply.patch.push_back(1);
      if (i + j + 1 < n) {
        ply.faces.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
        ply.patch.push_back(1);
      }
    }
  }
}

}  // namespace

std::string complete_mesh_file(const harness::Job& job) {
  return "meshes/" + case_variant(job) + ".complete.ply";
}

std::string holed_mesh_file(const harness::Job& job) {
  return "meshes/" + case_variant(job) + ".holed.ply";
}

std::string repaired_mesh_file(const harness::Job& job) {
  return "meshes/" + harness::file_stem_of_id(job.id()) + ".repaired.ply";
}

void write_plain_mesh(const Mesh& mesh, const std::filesystem::path& path,
                      const std::optional<render::Camera>& view) {
  ViewerPly ply = kept_faces(mesh, true);
  ply.view = view;
  write_whole(encode(ply), path);
}

void write_repaired_mesh(const Case& c, const Mesh& repaired, const std::filesystem::path& path,
                         const ViewerMeshOptions& options,
                         const embree::TriangleScene* complete_scene) {
  const double diagonal = bounding_box(c.complete).diagonal();
  // A scene of our own where none is given (fast to build: a closest point per split
  // corner; the answers are the same either way).
  std::optional<embree::TriangleScene> own;
  if (!complete_scene)
    own.emplace(c.complete, embree::SceneBuild::fast_build);
  const embree::TriangleScene& truth = complete_scene ? *complete_scene : *own;
  ViewerPly ply = kept_faces(repaired, false);
  ply.heat_scale_max_rel_diag = render::case_heat_scale(c).max_rel_diag;
  const double target = std::max(options.target_edge_rel_diag * diagonal, 1e-300);
  for (auto f : repaired.faces()) {
    if (!is_new(repaired, f))
      continue;
    const std::array<Point, 3> corners = face_corners(repaired, f);
    const double longest =
        std::max({(corners[1] - corners[0]).norm(), (corners[2] - corners[1]).norm(),
                  (corners[0] - corners[2]).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / target)), 1,
                             std::max(1, options.max_splits));
    add_split_face(ply, corners, n, truth, diagonal);
  }
  write_whole(encode(ply), path);
}

void write_job_meshes(const Case& c, const Mesh& repaired, const harness::Job& job,
                      const std::filesystem::path& out_dir, const ViewerMeshOptions& options,
                      const embree::TriangleScene* complete_scene) {
  const auto complete = out_dir / complete_mesh_file(job);
  const auto holed = out_dir / holed_mesh_file(job);
  if (!std::filesystem::exists(complete) || !std::filesystem::exists(holed)) {
    std::optional<render::Camera> view;
    if (!c.holes.empty())
      view = render::hole_view(c, 0).camera;
    write_plain_mesh(c.complete, complete, view);
    write_plain_mesh(c.input, holed, view);
  }
  write_repaired_mesh(c, repaired, out_dir / repaired_mesh_file(job), options, complete_scene);
}

}  // namespace holebench::viewer
