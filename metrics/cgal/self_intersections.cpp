// The metrics' one CGAL translation unit (a CGAL TU costs ~25 s and 2 GB to compile).
#include "metrics/validity.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <iterator>
#include <utility>
#include <vector>

namespace holebench::cgal {

SelfIntersections self_intersections(const Mesh& mesh) {
  using FacePair = std::pair<FaceHandle, FaceHandle>;
  std::vector<FacePair> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
      faces(mesh), mesh, std::back_inserter(pairs));
  SelfIntersections result;
  result.pairs = pairs.size();
  for (const auto& [f, g] : pairs) {
    if (is_new(mesh, f) || is_new(mesh, g))
      ++result.patch_pairs;
  }
  return result;
}

}  // namespace holebench::cgal
