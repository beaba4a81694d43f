// A CGAL translation unit of the methods: self-intersections of a patch and its surroundings.
#include "methods/common/patch_intersections.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <iterator>
#include <set>
#include <utility>

namespace holebench {

std::size_t patch_intersections(const Mesh& mesh, const std::vector<FaceHandle>& patch, int rings) {
  const std::set<FaceHandle> in_patch(patch.begin(), patch.end());
  std::set<VertexHandle> vertices;
  for (auto f : patch) {
    for (auto v : mesh.fv_range(f))
      vertices.insert(v);
  }
  std::set<FaceHandle> tested(patch.begin(), patch.end());
  for (int ring = 0; ring < rings; ++ring) {
    std::set<VertexHandle> next = vertices;
    for (auto v : vertices) {
      for (auto f : mesh.vf_range(v)) {
        tested.insert(f);
        for (auto w : mesh.fv_range(f))
          next.insert(w);
      }
    }
    vertices = std::move(next);
  }
  const std::vector<FaceHandle> range(tested.begin(), tested.end());
  std::vector<std::pair<FaceHandle, FaceHandle>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
      range, mesh, std::back_inserter(pairs));
  std::size_t count = 0;
  for (const auto& [f, g] : pairs)
    count += in_patch.count(f) > 0 || in_patch.count(g) > 0;
  return count;
}

std::size_t check_patch_intersections(const Mesh& mesh, std::size_t first_new_face,
                                      HoleReport& report) {
  std::vector<FaceHandle> patch;
  for (std::size_t f = first_new_face; f < mesh.n_faces(); ++f)
    patch.push_back(mesh.face_handle(static_cast<int>(f)));
  if (patch.empty())
    return 0;
  const std::size_t pairs = patch_intersections(mesh, patch);
  if (pairs > 0) {
    report.defect = kSelfIntersectingPatch;
    report.note += (report.note.empty() ? "" : "; ") +
                   std::string("the patch intersects itself or the mesh around the hole (") +
                   std::to_string(pairs) + " face pairs)";
  }
  return pairs;
}

}  // namespace holebench
