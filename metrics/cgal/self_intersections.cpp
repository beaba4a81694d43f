// The metrics' one CGAL translation unit (a CGAL TU costs ~25 s and 2 GB to compile).
#include "metrics/validity.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/self_intersections.h>

#include <algorithm>
#include <iterator>
#include <utility>
#include <vector>

namespace holebench::cgal {

namespace {

std::vector<FacePair> as_index_pairs(const std::vector<std::pair<FaceHandle, FaceHandle>>& pairs) {
  std::vector<FacePair> result;
  result.reserve(pairs.size());
  for (const auto& [f, g] : pairs)
    result.push_back(std::minmax(f.idx(), g.idx()));
  std::sort(result.begin(), result.end());
  return result;
}

}  // namespace

std::vector<FacePair> self_intersecting_pairs(const Mesh& mesh) {
  std::vector<std::pair<FaceHandle, FaceHandle>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
      faces(mesh), mesh, std::back_inserter(pairs));
  return as_index_pairs(pairs);
}

std::vector<FacePair> self_intersecting_pairs(const Mesh& mesh, const std::vector<int>& among) {
  std::vector<FaceHandle> range;
  range.reserve(among.size());
  for (int f : among)
    range.push_back(mesh.face_handle(f));
  std::vector<std::pair<FaceHandle, FaceHandle>> pairs;
  CGAL::Polygon_mesh_processing::self_intersections<CGAL::Sequential_tag>(
      range, mesh, std::back_inserter(pairs));
  return as_index_pairs(pairs);
}

}  // namespace holebench::cgal
