#include "methods/brep_guidance/brep_faces.h"

#include "core/geometry.h"

namespace holebench::brep_guidance {

BrepFaces extract_brep_faces(const Mesh& mesh, const PlanarSegmentationOptions& options,
                             FaceSource source) {
  BrepFaces faces;
  bool all_labelled = source == FaceSource::InputWhenPresent && mesh.n_faces() > 0;
  for (auto f : mesh.faces())
    all_labelled = all_labelled && region(mesh, f) != kNoRegion;
  if (!all_labelled) {
    PlanarSegmentation segmentation = segment_planar_regions(mesh, options);
    faces.face_region = std::move(segmentation.face_region);
    faces.planes = std::move(segmentation.planes);
    return faces;
  }
  faces.from_input = true;
  faces.face_region.resize(mesh.n_faces());
  int count = 0;
  for (auto f : mesh.faces()) {
    faces.face_region[f.idx()] = region(mesh, f);
    count = std::max(count, region(mesh, f) + 1);
  }
  faces.planes = fit_region_planes(mesh);
  return faces;
}

}  // namespace holebench::brep_guidance
