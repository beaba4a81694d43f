#include "methods/brep_guidance/brep_faces.h"

#include "core/coplanar_regions.h"
#include "core/geometry.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace holebench::brep_guidance {

std::vector<int> unite_coplanar_faces(const Mesh& mesh, const std::vector<PlaneFit>& planes,
                                      const UniteCoplanarOptions& options) {
  const int count = static_cast<int>(planes.size());
  std::vector<std::set<int>> vertices_of(count);
  for (auto f : mesh.faces()) {
    for (auto v : f.vertices())
      vertices_of[region(mesh, f)].insert(v.idx());
  }
  const double floor = options.residual_floor_rel_diag * bounding_box_diagonal(mesh);
  const double same_side = std::cos(options.max_normal_angle_degrees * M_PI / 180.0);
  return unite_neighbouring_regions(mesh, count, [&](int a, int b) {
    if (!planes[a].valid || !planes[b].valid ||
        OpenMesh::dot(planes[a].plane.normal, planes[b].plane.normal) < same_side)
      return false;
    std::vector<Point> points;
    for (int r : {a, b}) {
      for (int v : vertices_of[r])
        points.push_back(mesh.point(mesh.vertex_handle(v)));
    }
    const PlaneFit both = fit_plane(points);
    const double alone = std::max(planes[a].plane.rms_residual, planes[b].plane.rms_residual);
    return both.valid && both.plane.rms_residual <= options.residual_ratio * alone + floor;
  });
}

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
  const std::vector<int> face_of_region = unite_coplanar_faces(mesh, fit_region_planes(mesh));
  Mesh united = mesh;
  faces.face_region.resize(mesh.n_faces());
  for (auto f : mesh.faces()) {
    faces.face_region[f.idx()] = face_of_region[region(mesh, f)];
    set_region(united, united.face_handle(f.idx()), faces.face_region[f.idx()]);
  }
  faces.planes = fit_region_planes(united);
  return faces;
}

}  // namespace holebench::brep_guidance
