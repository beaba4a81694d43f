#include "metrics/embree/triangle_scene.h"

#include "core/distances.h"

#include <embree3/rtcore.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>

#include <unistd.h>

namespace holebench::embree {

namespace {

// Embree reports errors through one callback (its tutorials' pattern), on the thread that
// made the failing call; the message is kept there and thrown from our own frame after the
// call, never from inside Embree.
thread_local std::string last_embree_error;

void remember_embree_error(void*, RTCError code, const char* message) {
  last_embree_error = "Embree error " + std::to_string(code) + ": " + (message ? message : "");
}

// One Embree device for the process, as Embree advises (a device per scene costs a thread
// pool set-up and symbol lookups each time). Created on first use; a forked child (the
// harness runs each job in one) makes its own, since the parent's threads did not follow
// it. Never released: scenes may outlive any owner we could give it.
RTCDevice shared_device() {
  static std::mutex mutex;
  static RTCDevice device = nullptr;
  static pid_t owner = 0;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!device || owner != getpid()) {
    device = rtcNewDevice(nullptr);
    if (!device)
      throw std::runtime_error("Embree: cannot create a device");
    rtcSetDeviceErrorFunction(device, remember_embree_error, nullptr);
    owner = getpid();
  }
  return device;
}

struct PointQueryState {
  const std::vector<std::array<Point, 3>>* triangles;
  Point query;
  double coordinate_sum = 0.0;  // |x| + |y| + |z| of the query: the scale of its rounding
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
  // Padded by the single-precision rounding of the BVH's boxes and of the query point, then
  // rounded up, so that single precision never culls a closer triangle: the answer is the
  // nearest triangle (the smallest index among equals) whatever the BVH's layout.
  const double pad = single_precision_pad(state->coordinate_sum, distance);
  args->query->radius =
      std::nextafter(static_cast<float>(distance + pad), std::numeric_limits<float>::infinity());
  return true;
}

struct RadiusQueryState {
  const std::vector<std::array<Point, 3>>* triangles;
  Point query;
  double radius = 0.0;
  std::size_t max_primitives = std::numeric_limits<std::size_t>::max();
  bool overflow = false;
  std::vector<unsigned> primitives;
};

bool radius_callback(RTCPointQueryFunctionArguments* args) {
  auto* state = static_cast<RadiusQueryState*>(args->userPtr);
  if (state->overflow)
    return false;
  const auto& tri = (*state->triangles)[args->primID];
  if (point_triangle_distance(state->query, tri) <= state->radius)
    state->primitives.push_back(args->primID);
  if (state->primitives.size() <= state->max_primitives)
    return false;  // the radius never shrinks, unless the count is past the limit:
  state->overflow = true;
  args->query->radius = 0.0f;  // then the traversal is cut short
  return true;
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

// The mesh's faces but those deleted and not yet collected (OpenMesh's delete_face() only
// marks a face; garbage_collection() takes it out): a deleted face is no part of the surface,
// and the searches' shortcuts leave it out too (changed_faces_box, surface_change.h).
std::vector<int> faces_in_use(const Mesh& mesh) {
  std::vector<int> faces;
  faces.reserve(mesh.n_faces());
  for (std::size_t i = 0; i < mesh.n_faces(); ++i) {
    if (!mesh.status(FaceHandle(static_cast<int>(i))).deleted())
      faces.push_back(static_cast<int>(i));
  }
  return faces;
}

}  // namespace

TriangleScene::TriangleScene(const Mesh& mesh, SceneBuild build)
    : TriangleScene(mesh, faces_in_use(mesh), build) {}

TriangleScene::TriangleScene(const Mesh& mesh, const std::vector<int>& faces, SceneBuild build)
    : mesh_(&mesh) {
  device_ = shared_device();
  rtcRetainDevice(device_);
  last_embree_error.clear();
  scene_ = rtcNewScene(device_);
  // Embree 3 takes its Morton builder for low quality only in dynamic scenes.
  const bool fast_build = build == SceneBuild::fast_build;
  rtcSetSceneFlags(
      scene_, fast_build ? RTC_SCENE_FLAG_ROBUST | RTC_SCENE_FLAG_DYNAMIC : RTC_SCENE_FLAG_ROBUST);
  if (fast_build)
    rtcSetSceneBuildQuality(scene_, RTC_BUILD_QUALITY_LOW);

  // In increasing face order, so that the primitive order breaks ties as the face order
  // (callers mostly pass sorted lists: then no copy is sorted).
  std::vector<int> sorted_copy;
  const std::vector<int>* sorted_faces = &faces;
  if (!std::is_sorted(faces.begin(), faces.end()) ||
      std::adjacent_find(faces.begin(), faces.end()) != faces.end()) {
    sorted_copy = faces;
    std::sort(sorted_copy.begin(), sorted_copy.end());
    sorted_copy.erase(std::unique(sorted_copy.begin(), sorted_copy.end()), sorted_copy.end());
    sorted_faces = &sorted_copy;
  }
  const std::size_t count = sorted_faces->size();
  primitive_of_face_.assign(mesh.n_faces(), -1);
  triangles_.resize(count);
  face_of_primitive_.resize(count);

  RTCGeometry geometry = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), 3 * count));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), count));
  const Point* points = mesh.points();
  for (std::size_t t = 0; t < count; ++t) {
    const int face = (*sorted_faces)[t];
    // The corners in the face-vertex circulator's order, read straight off the halfedges.
    auto h = mesh.halfedge_handle(mesh.face_handle(face));
    for (int c = 0; c < 3; ++c, h = mesh.next_halfedge_handle(h)) {
      const Point& p = points[mesh.to_vertex_handle(h).idx()];
      triangles_[t][c] = p;
      for (int a = 0; a < 3; ++a)
        vertices[9 * t + 3 * c + a] = static_cast<float>(p[a]);
      indices[3 * t + c] = static_cast<unsigned>(3 * t + c);
    }
    primitive_of_face_[face] = static_cast<int>(t);
    face_of_primitive_[t] = face;
  }
  if (fast_build)
    rtcSetGeometryBuildQuality(geometry, RTC_BUILD_QUALITY_LOW);
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

TriangleScene::TriangleScene(const TriangleScene& base, const std::vector<int>& face_of_base_face,
                             const std::vector<int>& base_face_of_face, const Mesh& mesh,
                             const std::vector<int>& added, SceneBuild build)
    : mesh_(&mesh),
      base_(&base),
      face_of_base_face_(&face_of_base_face),
      base_face_of_face_(&base_face_of_face),
      added_(added.empty() ? nullptr : std::make_unique<TriangleScene>(mesh, added, build)) {}

std::size_t TriangleScene::triangle_count() const {
  if (base_)
    return base_->triangle_count() + (added_ ? added_->triangle_count() : 0);
  return triangles_.size();
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
  if (base_) {
    // The added part first (small, quick), then the base within its distance: the nearer
    // wins, the smaller face index (in `mesh`'s indices) among equals, as in a scene of the
    // whole mesh. The base's search is padded past the bound, so a face at the same distance
    // is seen.
    ClosestPoint from_added;
    from_added.distance = std::numeric_limits<double>::infinity();
    if (added_)
      from_added = added_->closest_point(p, distance_upper_bound);
    ClosestPoint from_base =
        base_->nearest_within(p, std::min(distance_upper_bound, from_added.distance));
    if (from_base.face < 0 && from_added.face < 0)
      from_base = base_->nearest_within(p, std::numeric_limits<double>::infinity());
    if (from_base.face >= 0)
      from_base.face = (*face_of_base_face_)[from_base.face];
    const bool added_wins =
        from_added.face >= 0 &&
        (from_base.face < 0 || from_added.distance < from_base.distance ||
         (from_added.distance == from_base.distance && from_added.face < from_base.face));
    return added_wins ? from_added : from_base;
  }
  ClosestPoint nearest = nearest_within(p, distance_upper_bound);
  if (nearest.face < 0 && std::isfinite(distance_upper_bound) && !triangles_.empty())
    return nearest_within(p, std::numeric_limits<double>::infinity());  // the bound did not hold
  return nearest;
}

ClosestPoint TriangleScene::nearest_within(const Point& p, double distance_upper_bound) const {
  PointQueryState state;
  state.triangles = &triangles_;
  state.query = p;
  state.coordinate_sum = coordinate_sum(p);
  RTCPointQuery query;
  query.x = static_cast<float>(p[0]);
  query.y = static_cast<float>(p[1]);
  query.z = static_cast<float>(p[2]);
  query.time = 0.0f;
  query.radius = std::numeric_limits<float>::infinity();
  if (std::isfinite(distance_upper_bound)) {
    // Padded by the single-precision rounding of the BVH's boxes and of the query point,
    // so that no triangle within the bound is culled; then rounded up.
    const double pad = single_precision_pad(coordinate_sum(p), distance_upper_bound);
    query.radius = std::nextafter(static_cast<float>(distance_upper_bound + pad),
                                  std::numeric_limits<float>::infinity());
  }
  ClosestPoint result;
  result.distance = std::numeric_limits<double>::infinity();
  if (triangles_.empty())
    return result;
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene_, &query, &context, closest_point_callback, &state);
  if (state.best_primitive == RTC_INVALID_GEOMETRY_ID)
    return result;
  result.point = state.best_point;
  result.distance = state.best_distance;
  result.face = face_of_primitive_[state.best_primitive];
  return result;
}

std::optional<std::vector<int>> TriangleScene::faces_within(const Point& p, double radius,
                                                            std::size_t max_faces) const {
  if (base_) {
    auto faces = base_->faces_within(p, radius, max_faces);
    if (!faces)
      return std::nullopt;
    for (int& face : *faces)
      face = (*face_of_base_face_)[face];
    if (!added_)
      return faces;
    const auto more = added_->faces_within(p, radius, max_faces);
    if (!more || faces->size() + more->size() > max_faces)
      return std::nullopt;
    faces->insert(faces->end(), more->begin(), more->end());
    std::sort(faces->begin(), faces->end());
    return faces;
  }
  RadiusQueryState state;
  state.max_primitives = max_faces;
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
  const double pad = single_precision_pad(coordinate_sum(p), radius);
  query.radius =
      std::nextafter(static_cast<float>(radius + pad), std::numeric_limits<float>::infinity());
  RTCPointQueryContext context;
  rtcInitPointQueryContext(&context);
  rtcPointQuery(scene_, &query, &context, radius_callback, &state);
  if (state.overflow)
    return std::nullopt;
  std::vector<int> faces;
  faces.reserve(state.primitives.size());
  for (unsigned primitive : state.primitives)
    faces.push_back(face_of_primitive_[primitive]);
  std::sort(faces.begin(), faces.end());
  return faces;
}

std::vector<int> TriangleScene::faces_within(const Point& p, double radius) const {
  return *faces_within(p, radius, std::numeric_limits<std::size_t>::max());
}

RayHit TriangleScene::intersect(const Point& origin, const Point& direction, double t_near,
                                double t_far) const {
  if (base_) {
    RayHit from_base = base_->intersect(origin, direction, t_near, t_far);
    if (from_base.hit)
      from_base.face = (*face_of_base_face_)[from_base.face];
    if (!added_)
      return from_base;
    const RayHit from_added = added_->intersect(origin, direction, t_near, t_far);
    const bool added_wins =
        from_added.hit && (!from_base.hit || from_added.distance < from_base.distance);
    return added_wins ? from_added : from_base;
  }
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

void TriangleScene::intersect_coherent(const Point& origin, const std::vector<Point>& directions,
                                       std::vector<RayHit>& hits) const {
  if (base_) {  // ray by ray through intersect(), which asks both parts
    hits.resize(directions.size());
    for (std::size_t i = 0; i < directions.size(); ++i)
      hits[i] = intersect(origin, directions[i]);
    return;
  }
  std::vector<RTCRayHit> stream(directions.size());
  for (std::size_t i = 0; i < directions.size(); ++i) {
    stream[i].ray = make_ray(origin, directions[i], 0.0, std::numeric_limits<double>::infinity());
    stream[i].hit.geomID = RTC_INVALID_GEOMETRY_ID;
    stream[i].hit.primID = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect1M(scene_, &context, stream.data(), static_cast<unsigned>(stream.size()),
                 sizeof(RTCRayHit));
  hits.assign(directions.size(), RayHit{});
  for (std::size_t i = 0; i < stream.size(); ++i) {
    if (stream[i].hit.geomID == RTC_INVALID_GEOMETRY_ID)
      continue;
    hits[i].hit = true;
    hits[i].distance = stream[i].ray.tfar;
    hits[i].face = face_of_primitive_[stream[i].hit.primID];
    const auto& tri = triangles_[stream[i].hit.primID];
    const Point n = OpenMesh::cross(tri[1] - tri[0], tri[2] - tri[0]);
    hits[i].normal = n / n.norm();
  }
}

bool TriangleScene::occluded(const Point& origin, const Point& direction, double t_near,
                             double t_far) const {
  if (base_) {
    return base_->occluded(origin, direction, t_near, t_far) ||
           (added_ && added_->occluded(origin, direction, t_near, t_far));
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay ray = make_ray(origin, direction, t_near, t_far);
  rtcOccluded1(scene_, &context, &ray);
  // rtcOccluded1 reports a blocked ray by setting tfar to -inf.
  return ray.tfar == -std::numeric_limits<float>::infinity();
}

const std::array<Point, 3>& TriangleScene::triangle_of_face(int face) const {
  if (base_) {
    const int base_face = base_face_of_face_->at(face);
    if (base_face >= 0 || !added_)
      return base_->triangle_of_face(base_face);
    return added_->triangle_of_face(face);
  }
  return triangles_.at(primitive_of_face_.at(face));
}

}  // namespace holebench::embree
