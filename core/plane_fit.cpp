#include "core/plane_fit.h"

#include "core/geometry.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <set>

namespace holebench {

PlaneFit fit_plane(const std::vector<Point>& points) {
  PlaneFit fit;
  if (points.size() < 3)
    return fit;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const Point& p : points)
    centroid += Eigen::Vector3d(p[0], p[1], p[2]);
  centroid /= static_cast<double>(points.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Point& p : points) {
    const Eigen::Vector3d d = Eigen::Vector3d(p[0], p[1], p[2]) - centroid;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance);
  const Eigen::Vector3d eigenvalues = solver.eigenvalues();  // ascending
  // Points on a line (or one point): the two smallest eigenvalues vanish.
  if (!(eigenvalues[1] > 1e-12 * eigenvalues[2]))
    return fit;
  const Eigen::Vector3d normal = solver.eigenvectors().col(0).normalized();
  fit.plane.point = Point(centroid.x(), centroid.y(), centroid.z());
  fit.plane.normal = Point(normal.x(), normal.y(), normal.z());
  fit.plane.rms_residual = std::sqrt(std::max(0.0, eigenvalues[0]) / points.size());
  fit.valid = true;
  return fit;
}

std::vector<PlaneFit> fit_region_planes(const Mesh& mesh) {
  const int count = region_count(mesh);
  std::vector<std::set<int>> region_vertices(count);
  std::vector<Point> mean_normal(count, Point(0.0, 0.0, 0.0));
  for (auto f : mesh.faces()) {
    const int id = region(mesh, f);
    if (id < 0)
      continue;
    for (auto v : f.vertices())
      region_vertices[id].insert(v.idx());
    mean_normal[id] += face_normal(mesh, f) * face_area(mesh, f);
  }
  std::vector<PlaneFit> fits(count);
  for (int id = 0; id < count; ++id) {
    std::vector<Point> points;
    for (int v : region_vertices[id])
      points.push_back(mesh.point(mesh.vertex_handle(v)));
    fits[id] = fit_plane(points);
    if (fits[id].valid && OpenMesh::dot(fits[id].plane.normal, mean_normal[id]) < 0.0) {
      fits[id].plane.normal = -fits[id].plane.normal;
    }
  }
  return fits;
}

}  // namespace holebench
