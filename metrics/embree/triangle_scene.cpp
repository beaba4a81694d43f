#include "metrics/embree/triangle_scene.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace holebench::embree {

Point closest_point_on_triangle(const Point& p, const Point& a, const Point& b, const Point& c) {
  using OpenMesh::dot;
  const Point ab = b - a;
  const Point ac = c - a;
  const Point ap = p - a;
  const double d1 = dot(ab, ap);
  const double d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
    return a;
  const Point bp = p - b;
  const double d3 = dot(ab, bp);
  const double d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
    return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
    return a + ab * (d1 / (d1 - d3));
  const Point cp = p - c;
  const double d5 = dot(ab, cp);
  const double d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
    return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
    return a + ac * (d2 / (d2 - d6));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
    return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  }
  const double denominator = 1.0 / (va + vb + vc);
  return a + ab * (vb * denominator) + ac * (vc * denominator);
}

namespace {

// Embree reports errors through one callback (its tutorials' pattern); the message is
// kept and thrown from our own frame after the call, never from inside Embree.
void remember_embree_error(void* user, RTCError code, const char* message) {
  auto* last = static_cast<std::string*>(user);
  *last = "Embree error " + std::to_string(code) + ": " + (message ? message : "");
}

thread_local std::string last_embree_error;

struct PointQueryState {
  const std::vector<std::array<Point, 3>>* triangles;
  Point query;
  double best_distance = std::numeric_limits<double>::infinity();
  unsigned best_primitive = RTC_INVALID_GEOMETRY_ID;
  Point best_point;
};

bool closest_point_callback(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<PointQueryState*>(args->userPtr);
  const auto& tri = (*state->triangles)[args->primID];
  const Point q = closest_point_on_triangle(state->query, tri[0], tri[1], tri[2]);
  const double distance = (q - state->query).norm();
  const bool better = distance < state->best_distance ||
                      (distance == state->best_distance && args->primID < state->best_primitive);
  if (!better)
    return false;
  state->best_distance = distance;
  state->best_primitive = args->primID;
  state->best_point = q;
  // Round the radius up so that single precision never culls a closer triangle.
  args->query->radius =
      std::nextafter(static_cast<float>(distance), std::numeric_limits<float>::infinity());
  return true;
}

struct RadiusQueryState {
  const std::vector<std::array<Point, 3>>* triangles;
  Point query;
  double radius = 0.0;
  std::vector<unsigned> primitives;
};

bool radius_callback(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<RadiusQueryState*>(args->userPtr);
  const auto& tri = (*state->triangles)[args->primID];
  const Point q = closest_point_on_triangle(state->query, tri[0], tri[1], tri[2]);
  if ((q - state->query).norm() <= state->radius)
    state->primitives.push_back(args->primID);
  return false;  // the radius never shrinks
}

RTCRay make_ray(const Point& origin, const Point& direction, double t_near, double t_far) {
  RTCRay ray{};
  ray.org_x = static_cast<float>(origin[0]);
  ray.org_y = static_cast<float>(origin[1]);
  ray.org_z = static_cast<float>(origin[2]);
  const Point d = direction / direction.norm();
  ray.dir_x = static_cast<float>(d[0]);
  ray.dir_y = static_cast<float>(d[1]);
  ray.dir_z = static_cast<float>(d[2]);
  ray.tnear = static_cast<float>(t_near);
  ray.tfar = std::isinf(t_far) ? std::numeric_limits<float>::infinity() : static_cast<float>(t_far);
  ray.time = 0.0f;
  ray.mask = 0xFFFFFFFFu;
  ray.id = 0;
  ray.flags = 0;
  return ray;
}

}  // namespace

namespace {

std::vector<int> all_faces(const Mesh& mesh) {
  std::vector<int> faces(mesh.n_faces());
  for (std::size_t i = 0; i < faces.size(); ++i)
    faces[i] = static_cast<int>(i);
  return faces;
}

}  // namespace

TriangleScene::TriangleScene(const Mesh& mesh) : TriangleScene(mesh, all_faces(mesh)) {}

TriangleScene::TriangleScene(const Mesh& mesh, const std::vector<int>& faces) {
  device_ = rtcNewDevice(nullptr);
  if (!device_)
    throw std::runtime_error("Embree: cannot create a device");
  rtcSetDeviceErrorFunction(device_, remember_embree_error, &last_embree_error);
  scene_ = rtcNewScene(device_);
  rtcSetSceneFlags(scene_, RTC_SCENE_FLAG_ROBUST);

  // In increasing face order, so that the primitive order breaks ties as the face order.
  std::vector<int> sorted_faces = faces;
  std::sort(sorted_faces.begin(), sorted_faces.end());
  sorted_faces.erase(std::unique(sorted_faces.begin(), sorted_faces.end()), sorted_faces.end());
  primitive_of_face_.assign(mesh.n_faces(), -1);
  for (int face : sorted_faces) {
    const auto f = mesh.face_handle(face);
    std::array<Point, 3> tri;
    int k = 0;
    for (auto v : mesh.fv_range(f))
      tri[k++] = mesh.point(v);
    primitive_of_face_[f.idx()] = static_cast<int>(triangles_.size());
    triangles_.push_back(tri);
    face_of_primitive_.push_back(f.idx());
  }

  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               3 * triangles_.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), triangles_.size()));
  for (std::size_t t = 0; t < triangles_.size(); ++t) {
    for (int c = 0; c < 3; ++c) {
      for (int a = 0; a < 3; ++a)
        vertices[9 * t + 3 * c + a] = static_cast<float>(triangles_[t][c][a]);
      indices[3 * t + c] = static_cast<unsigned>(3 * t + c);
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(scene_, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(scene_);
  if (rtcGetDeviceError(device_) != RTC_ERROR_NONE) {
    const std::string message = last_embree_error;
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
    throw std::runtime_error(message.empty() ? "Embree: cannot build the scene" : message);
  }
}

TriangleScene::~TriangleScene() {
  if (scene_)
    rtcReleaseScene(scene_);
  if (device_)
    rtcReleaseDevice(device_);
}

ClosestPoint TriangleScene::closest_point(const Point& p) const {
  return closest_point(p, std::numeric_limits<double>::infinity());
}

ClosestPoint TriangleScene::closest_point(const Point& p, double distance_upper_bound) const {
  PointQueryState state;
  state.triangles = &triangles_;
  state.query = p;
  RTCPointQuery query;
  query.x = static_cast<float>(p[0]);
  query.y = static_cast<float>(p[1]);
  query.z = static_cast<float>(p[2]);
  query.time = 0.0f;
  query.radius = std::numeric_limits<float>::infinity();
  if (std::isfinite(distance_upper_bound)) {
    // Padded by the single-precision rounding of the BVH's boxes and of the query point,
    // so that no triangle within the bound is culled; then rounded up.
    const double pad =
        1e-6 * (std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) + distance_upper_bound);
    query.radius = std::nextafter(static_cast<float>(distance_upper_bound + pad),
                                  std::numeric_limits<float>::infinity());
  }
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene_, &query, &context, closest_point_callback, &state);
  ClosestPoint result;
  if (state.best_primitive == RTC_INVALID_GEOMETRY_ID) {
    if (std::isfinite(distance_upper_bound) && !triangles_.empty())
      return closest_point(p);  // the bound did not hold: search without it
    result.distance = std::numeric_limits<double>::infinity();
    return result;
  }
  result.point = state.best_point;
  result.distance = state.best_distance;
  result.face = face_of_primitive_[state.best_primitive];
  return result;
}

std::vector<int> TriangleScene::faces_within(const Point& p, double radius) const {
  RadiusQueryState state;
  state.triangles = &triangles_;
  state.query = p;
  state.radius = radius;
  RTCPointQuery query;
  query.x = static_cast<float>(p[0]);
  query.y = static_cast<float>(p[1]);
  query.z = static_cast<float>(p[2]);
  query.time = 0.0f;
  // Rounded up (and padded by the coordinates' single-precision rounding) so that the BVH
  // never culls a triangle within the radius.
  const double pad = 1e-6 * (std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]) + radius);
  query.radius =
      std::nextafter(static_cast<float>(radius + pad), std::numeric_limits<float>::infinity());
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene_, &query, &context, radius_callback, &state);
  std::vector<int> faces;
  faces.reserve(state.primitives.size());
  for (unsigned primitive : state.primitives)
    faces.push_back(face_of_primitive_[primitive]);
  std::sort(faces.begin(), faces.end());
  return faces;
}

RayHit TriangleScene::intersect(const Point& origin, const Point& direction, double t_near,
                                double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit ray_hit{};
  ray_hit.ray = make_ray(origin, direction, t_near, t_far);
  ray_hit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  ray_hit.hit.primID = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(scene_, &context, &ray_hit);
  RayHit result;
  if (ray_hit.hit.geomID == RTC_INVALID_GEOMETRY_ID)
    return result;
  result.hit = true;
  result.distance = ray_hit.ray.tfar;
  result.face = face_of_primitive_[ray_hit.hit.primID];
  const auto& tri = triangles_[ray_hit.hit.primID];
  Point n = OpenMesh::cross(tri[1] - tri[0], tri[2] - tri[0]);
  result.normal = n / n.norm();
  return result;
}

bool TriangleScene::occluded(const Point& origin, const Point& direction, double t_near,
                             double t_far) const {
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(scene_, &context, &ray);
  // rtcOccluded1 reports a blocked ray by setting tfar to -inf.
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

const std::array<Point, 3>& TriangleScene::triangle_of_face(int face) const {
  return triangles_.at(primitive_of_face_.at(face));
}

}  // namespace holebench::embree
