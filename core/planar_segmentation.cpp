#include "core/planar_segmentation.h"

#include "core/geometry.h"
#include "core/portable_math.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

namespace holebench {
namespace {

// Residual of the plane fitted to a face's vertices and its neighbours' vertices.
double local_residual(const Mesh& mesh, FaceHandle f) {
  std::vector<Point> points;
  for (auto v : mesh.fv_range(f)) {
    for (auto w : mesh.vv_range(v))
      points.push_back(mesh.point(w));
    points.push_back(mesh.point(v));
  }
  const PlaneFit fit = fit_plane(points);
  return fit.valid ? fit.plane.rms_residual : 0.0;
}

PlaneFit fit_faces(const Mesh& mesh, const std::vector<FaceHandle>& faces) {
  std::vector<Point> points;
  Point normal(0, 0, 0);
  for (auto f : faces) {
    for (auto v : mesh.fv_range(f))
      points.push_back(mesh.point(v));
    normal += face_normal(mesh, f) * face_area(mesh, f);
  }
  PlaneFit fit = fit_plane(points);
  if (!fit.valid && !faces.empty()) {  // one triangle: its own plane
    fit.valid = true;
    fit.plane.point = face_centroid(mesh, faces.front());
    fit.plane.normal = face_normal(mesh, faces.front());
  }
  if (fit.valid && OpenMesh::dot(fit.plane.normal, normal) < 0.0)
    fit.plane.normal = -fit.plane.normal;
  return fit;
}

}  // namespace

PlanarSegmentation segment_planar_regions(const Mesh& mesh,
                                          const PlanarSegmentationOptions& options) {
  PlanarSegmentation result;
  const std::size_t n = mesh.n_faces();
  result.face_region.assign(n, kNoRegion);
  std::vector<double> residual(n, 0.0);
  for (auto f : mesh.faces())
    residual[f.idx()] = local_residual(mesh, f);
  std::vector<double> sorted = residual;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  result.distance_tolerance =
      std::max(options.residual_factor * median,
               options.min_tolerance_rel_diag * bounding_box_diagonal(mesh));
  const double cos_angle = portable_cos(options.max_normal_angle_degrees * M_PI / 180.0);

  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return residual[a] < residual[b]; });

  for (int seed_index : order) {
    if (result.face_region[seed_index] != kNoRegion)
      continue;
    const int id = static_cast<int>(result.planes.size());
    const FaceHandle seed = mesh.face_handle(seed_index);
    std::vector<FaceHandle> members{seed};
    result.face_region[seed_index] = id;
    PlaneFit plane = fit_faces(mesh, members);
    std::size_t refit_at = 8;
    // Breadth-first growth; the plane is refitted whenever the region doubles.
    for (std::size_t next = 0; next < members.size(); ++next) {
      for (auto g : mesh.ff_range(members[next])) {
        if (result.face_region[g.idx()] != kNoRegion)
          continue;
        if (OpenMesh::dot(face_normal(mesh, g), plane.plane.normal) < cos_angle)
          continue;
        if (std::abs(plane.plane.signed_distance(face_centroid(mesh, g))) >
            result.distance_tolerance)
          continue;
        result.face_region[g.idx()] = id;
        members.push_back(g);
        if (members.size() >= refit_at) {
          plane = fit_faces(mesh, members);
          refit_at *= 2;
        }
      }
    }
    result.planes.push_back(fit_faces(mesh, members));
  }

  // Merge tiny regions (noise specks) into the neighbour they share most edges with.
  std::vector<int> size(result.planes.size(), 0);
  for (int r : result.face_region)
    ++size[r];
  for (auto f : mesh.faces()) {
    const int r = result.face_region[f.idx()];
    if (size[r] >= options.min_region_faces)
      continue;
    std::map<int, int> shared;
    for (auto g : mesh.ff_range(f)) {
      const int s = result.face_region[g.idx()];
      if (s != r && size[s] >= options.min_region_faces)
        ++shared[s];
    }
    if (shared.empty())
      continue;
    const auto best =
        std::max_element(shared.begin(), shared.end(),
                         [](const auto& a, const auto& b) { return a.second < b.second; });
    --size[r];
    ++size[best->first];
    result.face_region[f.idx()] = best->first;
  }
  // Renumber the surviving regions in order of first face and refit their planes.
  std::map<int, int> renumber;
  for (auto f : mesh.faces())
    renumber.emplace(result.face_region[f.idx()], static_cast<int>(renumber.size()));
  std::vector<std::vector<FaceHandle>> members(renumber.size());
  for (auto f : mesh.faces()) {
    int& r = result.face_region[f.idx()];
    r = renumber[r];
    members[r].push_back(f);
  }
  result.planes.clear();
  for (const auto& faces : members)
    result.planes.push_back(fit_faces(mesh, faces));
  return result;
}

}  // namespace holebench
