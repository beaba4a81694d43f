#include "harness/outputs/viewer/viewer_mesh.h"

#include "harness/outputs/file_names.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "harness/outputs/file_bytes.h"
#include "harness/outputs/gzip_bytes.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/heat_map.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/kept_faces.h"

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
#include <unordered_map>
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
  std::vector<std::array<std::int32_t, 2>> sewn;        ///< patch vertex, input vertex
  std::vector<std::int32_t> dropped_faces;              ///< input faces not kept
  /// A patch file: faces carry `splits` and `split_quality`, and the elements sewn_vertex and
  /// dropped_face follow the edges.
  bool patch_file = false;
  std::vector<std::uint8_t> splits;               ///< by face: n (0: not split)
  std::vector<std::vector<float>> split_quality;  ///< by face: the split vertices' distances
  double heat_scale_max_rel_diag = 0.0;           ///< 0: not written
  std::optional<render::Camera> view;             ///< written where set
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
      "property uchar patch\n{}element edge {}\nproperty int vertex1\nproperty int vertex2\n",
      ply.vertices.size(), ply.faces.size(),
      ply.patch_file ? "property uchar splits\nproperty list uchar float split_quality\n" : "",
      ply.open_edges.size());
  if (ply.patch_file) {
    out += fmt::format(
        "element sewn_vertex {}\nproperty int vertex\nproperty int input_vertex\n"
        "element dropped_face {}\nproperty int input_face\n",
        ply.sewn.size(), ply.dropped_faces.size());
  }
  out += "end_header\n";
  for (const auto& v : ply.vertices) {
    for (float x : v)
      put(out, x);
  }
  for (std::size_t f = 0; f < ply.faces.size(); ++f) {
    put(out, static_cast<std::uint8_t>(3));
    for (std::int32_t i : ply.faces[f])
      put(out, i);
    put(out, ply.patch[f]);
    if (ply.patch_file) {
      put(out, ply.splits[f]);
      put(out, static_cast<std::uint8_t>(ply.split_quality[f].size()));
      for (float q : ply.split_quality[f])
        put(out, q);
    }
  }
  for (const auto& edge : ply.open_edges) {
    put(out, edge[0]);
    put(out, edge[1]);
  }
  for (const auto& pair : ply.sewn) {
    put(out, pair[0]);
    put(out, pair[1]);
  }
  for (std::int32_t face : ply.dropped_faces)
    put(out, face);
  return out;
}

/// The most splits of a face whose (n + 1)(n + 2) / 2 distances fit a PLY list with a uchar
/// count.
constexpr int kMostSplits = 20;

constexpr const char* kScriptStart = "holebenchViewer.receiveMesh(\"";

/// Writes the PLY as a viewer file (a script holding its gzip stream in base64) under a
/// temporary name, then renames: readers see the whole file or none.
void write_whole(const std::string& ply_bytes, const std::filesystem::path& path) {
  std::filesystem::create_directories(path.parent_path());
  const auto temporary = path.string() + fmt::format(".{}.tmp", ::getpid());
  {
    std::ofstream out(temporary, std::ios::binary);
    out << kScriptStart << path.filename().string() << "\", \""
        << harness::base64(harness::gzip_bytes(ply_bytes)) << "\");\n";
    if (!out)
      throw std::runtime_error(path.string() + ": cannot write");
  }
  std::filesystem::rename(temporary, path);
}

std::array<float, 4> vertex(const Point& p, double quality) {
  return {static_cast<float>(p[0]), static_cast<float>(p[1]), static_cast<float>(p[2]),
          static_cast<float>(quality)};
}

/// The mesh's faces with its own vertices (quality 0) and its open edges.
ViewerPly plain_ply(const Mesh& mesh) {
  ViewerPly ply;
  for (auto v : mesh.vertices())
    ply.vertices.push_back(vertex(mesh.point(v), 0.0));
  for (auto f : mesh.faces()) {
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

/// The distances at the vertices of the triangle's split into n x n pieces: vertex (i, j),
/// i + j <= n, at corners[0] + (i (corners[1] - corners[0]) + j (corners[2] - corners[0])) / n,
/// row by row (j), i along each row.
std::vector<float> split_quality(const std::array<Point, 3>& corners, int n,
                                 const embree::TriangleScene& truth, double diagonal) {
  std::vector<float> quality;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i + j <= n; ++i) {
      const Point p = corners[0] + ((corners[1] - corners[0]) * i + (corners[2] - corners[0]) * j) /
                                       static_cast<double>(n);
      quality.push_back(static_cast<float>(truth.closest_point(p).distance / diagonal));
    }
  }
  return quality;
}

}  // namespace

std::string complete_mesh_file(const harness::Job& job) {
  return "meshes/" + case_variant(job) + ".complete.js";
}

std::string holed_mesh_file(const harness::Job& job) {
  return "meshes/" + case_variant(job) + ".holed.js";
}

std::string patch_mesh_file(const harness::Job& job) {
  return "meshes/" + harness::file_stem_of_id(job.id()) + ".patch.js";
}

void write_plain_mesh(const Mesh& mesh, const std::filesystem::path& path,
                      const std::optional<render::Camera>& view) {
  ViewerPly ply = plain_ply(mesh);
  ply.view = view;
  write_whole(encode(ply), path);
}

std::string read_viewer_ply(const std::filesystem::path& path) {
  const std::string text = harness::read_bytes(path);
  const std::string start = std::string(kScriptStart) + path.filename().string() + "\", \"";
  const std::size_t end = text.rfind("\");");
  if (text.rfind(start, 0) != 0 || end == std::string::npos || end < start.size())
    throw std::runtime_error(path.string() + ": not a viewer mesh file");
  return harness::gunzip_bytes(harness::from_base64(text.substr(start.size(), end - start.size())));
}

void write_patch_mesh(const Case& c, const Mesh& repaired, const std::filesystem::path& path,
                      const ViewerMeshOptions& options,
                      const embree::TriangleScene* complete_scene) {
  const double diagonal = bounding_box(c.complete).diagonal();
  // A scene of our own where none is given (fast to build: a closest point per split
  // corner; the answers are the same either way).
  std::optional<embree::TriangleScene> own;
  if (!complete_scene)
    own.emplace(c.complete, embree::SceneBuild::fast_build);
  const embree::TriangleScene& truth = complete_scene ? *complete_scene : *own;
  const KeptFaces kept = kept_faces(c.input, repaired);
  ViewerPly ply;
  ply.patch_file = true;
  ply.heat_scale_max_rel_diag = render::case_heat_scale(c).max_rel_diag;
  // The input vertex a repaired vertex is (its index and point), or -1.
  const auto input_vertex = [&](VertexHandle v) {
    const bool same = v.idx() < static_cast<int>(c.input.n_vertices()) &&
                      c.input.point(VertexHandle(v.idx())) == repaired.point(v);
    return same ? v.idx() : -1;
  };
  const auto add_vertex = [&](const Point& p, double quality, int input) {
    const auto index = static_cast<std::int32_t>(ply.vertices.size());
    ply.vertices.push_back(vertex(p, quality));
    if (input >= 0)
      ply.sewn.push_back({index, input});
    return index;
  };
  // The vertices of the patch's faces and of the open edges, each once, with its distance.
  std::unordered_map<int, std::int32_t> patch_vertex;
  const auto index_of = [&](VertexHandle v) {
    const auto [it, inserted] = patch_vertex.try_emplace(v.idx(), 0);
    if (inserted) {
      const Point& p = repaired.point(v);
      it->second = add_vertex(p, truth.closest_point(p).distance / diagonal, input_vertex(v));
    }
    return it->second;
  };
  const double target = std::max(options.target_edge_rel_diag * diagonal, 1e-300);
  for (auto f : repaired.faces()) {
    if (kept.input_face_of_repaired[f.idx()] >= 0)
      continue;
    std::array<std::int32_t, 3> face{};
    int i = 0;
    for (auto v : repaired.fv_range(f)) {
      if (i < 3)
        face[i] = index_of(v);
      ++i;
    }
    ply.faces.push_back(face);
    const bool patch = is_new(repaired, f);  // else an input face the method changed: grey
    ply.patch.push_back(patch ? 1 : 0);
    if (!patch) {
      ply.splits.push_back(0);
      ply.split_quality.emplace_back();
      continue;
    }
    const std::array<Point, 3> corners = face_corners(repaired, f);
    const double longest =
        std::max({(corners[1] - corners[0]).norm(), (corners[2] - corners[1]).norm(),
                  (corners[0] - corners[2]).norm()});
    const int n = std::clamp(static_cast<int>(std::ceil(longest / target)), 1,
                             std::clamp(options.max_splits, 1, kMostSplits));
    ply.splits.push_back(static_cast<std::uint8_t>(n));
    ply.split_quality.push_back(split_quality(corners, n, truth, diagonal));
  }
  for (const auto& loop : find_boundary_loops(repaired)) {
    for (auto h : loop.halfedges)
      ply.open_edges.push_back(
          {index_of(repaired.from_vertex_handle(h)), index_of(repaired.to_vertex_handle(h))});
  }
  for (std::size_t f = 0; f < kept.repaired_face_of_input.size(); ++f) {
    if (kept.repaired_face_of_input[f] < 0)
      ply.dropped_faces.push_back(static_cast<std::int32_t>(f));
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
  write_patch_mesh(c, repaired, out_dir / patch_mesh_file(job), options, complete_scene);
}

}  // namespace holebench::viewer
