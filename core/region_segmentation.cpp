#include "core/region_segmentation.h"

#include "core/geometry.h"

#include <cmath>

namespace holebench {

SegmentationResult segment_regions(const Mesh& mesh, const SegmentationOptions& options) {
  const double threshold = options.sharp_angle_degrees * M_PI / 180.0;
  std::vector<char> sharp(mesh.n_edges(), 0);
  for (auto e : mesh.edges()) {
    sharp[e.idx()] = !e.is_boundary() && std::abs(signed_dihedral_angle(mesh, e)) > threshold;
  }

  SegmentationResult result;
  result.face_region.assign(mesh.n_faces(), kNoRegion);
  std::vector<OpenMesh::SmartFaceHandle> stack;
  for (auto seed : mesh.faces()) {
    if (result.face_region[seed.idx()] != kNoRegion)
      continue;
    const int id = result.region_count++;
    result.face_region[seed.idx()] = id;
    stack.push_back(seed);
    while (!stack.empty()) {
      const auto f = stack.back();
      stack.pop_back();
      for (auto h : f.halfedges()) {
        if (sharp[h.edge().idx()])
          continue;
        const auto neighbour = h.opp().face();
        if (!neighbour.is_valid() || result.face_region[neighbour.idx()] != kNoRegion)
          continue;
        result.face_region[neighbour.idx()] = id;
        stack.push_back(neighbour);
      }
    }
  }
  for (auto e : mesh.edges()) {
    if (e.is_boundary())
      continue;
    if (result.face_region[e.h0().face().idx()] != result.face_region[e.h1().face().idx()]) {
      result.sharp_edges.push_back(e);
    }
  }
  return result;
}

void assign_regions(Mesh& mesh, const SegmentationResult& segmentation) {
  for (auto f : mesh.faces())
    set_region(mesh, f, segmentation.face_region[f.idx()]);
}

}  // namespace holebench
