#include "generators/hole_punch.h"

#include "core/geometry.h"
#include "core/mesh_builder.h"

#include <algorithm>

namespace holebench::generators {

std::vector<int> faces_in_ball(const Mesh& mesh, const Point& center, double radius) {
  std::vector<int> faces;
  for (auto f : mesh.faces()) {
    if ((face_centroid(mesh, f) - center).norm() <= radius)
      faces.push_back(f.idx());
  }
  return faces;
}

namespace {

// A vertex is kept manifold when its remaining faces form one fan: walking around it,
// removed and kept faces switch at most twice.
bool leaves_non_manifold_vertex(const Mesh& mesh, VertexHandle v,
                                const std::vector<char>& removed) {
  int switches = 0;
  bool any_removed = false;
  std::vector<char> ring;
  for (auto f : mesh.vf_ccw_range(v))
    ring.push_back(removed[f.idx()]);
  for (char r : ring)
    any_removed = any_removed || r;
  if (!any_removed || mesh.is_boundary(v))
    return false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    if (ring[i] != ring[(i + 1) % ring.size()])
      ++switches;
  }
  return switches > 2;
}

bool is_hanging(const Mesh& mesh, FaceHandle f, const std::vector<char>& removed) {
  for (auto h : mesh.fh_range(f)) {
    const auto neighbour = mesh.opposite_face_handle(h);
    if (neighbour.is_valid() && !removed[neighbour.idx()])
      return false;
  }
  return true;
}

}  // namespace

PunchResult punch_faces(const Mesh& complete, std::vector<int> faces) {
  std::vector<char> removed(complete.n_faces(), 0);
  for (int f : faces)
    removed[f] = 1;
  // Grow the removed set until the rest is manifold; each pass only adds faces.
  for (bool changed = true; changed;) {
    changed = false;
    for (auto v : complete.vertices()) {
      if (!leaves_non_manifold_vertex(complete, v, removed))
        continue;
      for (auto f : complete.vf_range(v))
        removed[f.idx()] = 1;
      changed = true;
    }
    for (auto f : complete.faces()) {
      if (!removed[f.idx()] && is_hanging(complete, f, removed)) {
        removed[f.idx()] = 1;
        changed = true;
      }
    }
  }

  PunchResult result;
  TriangleSoup soup;
  std::vector<int> new_index(complete.n_vertices(), -1);
  for (auto f : complete.faces()) {
    if (removed[f.idx()]) {
      result.removed_faces.push_back(f.idx());
      continue;
    }
    for (auto v : f.vertices())
      new_index[v.idx()] = 0;
  }
  for (auto v : complete.vertices()) {
    if (new_index[v.idx()] < 0)
      continue;
    new_index[v.idx()] = static_cast<int>(soup.points.size());
    soup.points.push_back(complete.point(v));
    result.vertex_to_complete.push_back(v.idx());
  }
  for (auto f : complete.faces()) {
    if (removed[f.idx()])
      continue;
    std::array<int, 3> tri{};
    int k = 0;
    for (auto v : f.vertices())
      tri[k++] = new_index[v.idx()];
    soup.triangles.push_back(tri);
    soup.regions.push_back(region(complete, f));
  }
  result.holed = build_mesh(soup, BuildOptions{"hole punch"});
  return result;
}

}  // namespace holebench::generators
