#include "harness/outputs/render/close_up.h"

#include "core/boundary_loops.h"
#include "core/geometry.h"
#include "harness/outputs/render/case_view.h"
#include "metrics/embree/near_face_distance.h"
#include "metrics/embree/triangle_scene.h"
#include "metrics/kept_faces.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace holebench::render {
namespace {

constexpr double kFieldOfViewDegrees = 40.0;

/// Area-weighted mean outward normal and boundary of a hole's removed faces.
struct RemovedSurface {
  Point normal{0, 0, 0};  ///< not normalised; zero where the normals cancel
  std::vector<Point> region_normals;
  std::vector<Point> boundary_points;
};

/// `hole`'s removed faces; a face counts as kept when no hole of the case removed it.
RemovedSurface removed_surface(const Case& c, std::size_t hole_index) {
  const Mesh& complete = c.complete;
  const HoleTruth& hole = c.holes.at(hole_index);
  RemovedSurface out;
  const std::set<int> removed(hole.removed_faces.begin(), hole.removed_faces.end());
  std::set<int> removed_by_any;
  for (const auto& other : c.holes)
    removed_by_any.insert(other.removed_faces.begin(), other.removed_faces.end());
  const auto kept = [&](FaceHandle f) { return !f.is_valid() || !removed_by_any.count(f.idx()); };
  std::map<int, Point> by_region;
  for (int index : hole.removed_faces) {
    const FaceHandle f = complete.face_handle(index);
    const Point n = face_normal(complete, f) * face_area(complete, f);
    out.normal += n;
    // Point() leaves its coordinates uninitialised (OpenMesh): each sum starts at zero.
    by_region.try_emplace(region(complete, f), 0.0, 0.0, 0.0).first->second += n;
  }
  for (const auto& [id, n] : by_region) {
    if (n.norm() > 0.0)
      out.region_normals.push_back(n / n.norm());
  }
  std::set<int> vertices;
  for (auto e : complete.edges()) {
    const auto h0 = complete.halfedge_handle(e, 0);
    const auto h1 = complete.halfedge_handle(e, 1);
    const auto f0 = complete.face_handle(h0);
    const auto f1 = complete.face_handle(h1);
    const bool in0 = f0.is_valid() && removed.count(f0.idx());
    const bool in1 = f1.is_valid() && removed.count(f1.idx());
    if ((in0 && kept(f1)) || (in1 && kept(f0))) {
      vertices.insert(complete.from_vertex_handle(h0).idx());
      vertices.insert(complete.to_vertex_handle(h0).idx());
    }
  }
  for (int v : vertices)
    out.boundary_points.push_back(complete.point(complete.vertex_handle(v)));
  return out;
}

/// Candidate viewing directions (from the camera towards the hole), best guesses first.
std::vector<Point> candidate_directions(const RemovedSurface& surface) {
  std::vector<Point> outward;
  const double length = surface.normal.norm();
  if (length > 1e-12) {
    const Point n = surface.normal / length;
    outward.push_back(n);
    Point u = OpenMesh::cross(n, std::abs(n[2]) < 0.9 ? Point(0, 0, 1) : Point(1, 0, 0));
    u /= u.norm();
    const Point v = OpenMesh::cross(n, u);
    for (const Point& t : {u, -u, v, -v})
      outward.push_back(n + t * 0.5);
  }
  for (const auto& n : surface.region_normals)
    outward.push_back(n);
  // Then directions spread over the sphere (a Fibonacci lattice), for loops that the
  // normals do not show whole.
  const int spread = 48;
  for (int i = 0; i < spread; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / spread;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double angle = i * M_PI * (3.0 - std::sqrt(5.0));
    outward.push_back(Point(r * std::cos(angle), r * std::sin(angle), z));
  }
  std::vector<Point> directions;
  for (const auto& n : outward) {
    const double norm = n.norm();
    if (std::isfinite(norm) && norm > 1e-9)
      directions.push_back(-n / norm);
  }
  return directions;
}

Point mean(const std::vector<Point>& points) {
  Point sum(0, 0, 0);
  for (const auto& p : points)
    sum += p;
  return points.empty() ? sum : sum / static_cast<double>(points.size());
}

double visible_share(const embree::TriangleScene& holed, const Camera& camera,
                     const std::vector<Point>& points, double tolerance) {
  if (points.empty())
    return 0.0;
  const Point eye = eye_of(camera);
  std::size_t visible = 0;
  for (const auto& p : points) {
    const Point d = p - eye;
    const double distance = d.norm();
    if (distance <= tolerance || !holed.occluded(eye, d / distance, 0.0, distance - tolerance))
      ++visible;
  }
  return static_cast<double>(visible) / static_cast<double>(points.size());
}

Rgb shaded_grey() {
  return {0.62f, 0.62f, 0.62f};
}

/// Arrows as now (case_view.h's add_guidance_arrows)
/// and the open boundary loops of the repaired mesh.
Overlay job_overlay(const Case& c, const MethodResult& result) {
  Overlay overlay;
  add_guidance_arrows(overlay, c, result);
  for (const auto& loop : find_boundary_loops(result.repaired)) {
    for (auto h : loop.halfedges) {
      overlay.lines.push_back({result.repaired.point(result.repaired.from_vertex_handle(h)),
                               result.repaired.point(result.repaired.to_vertex_handle(h)),
                               open_hole_colour(), 3.0f});
    }
  }
  return overlay;
}

SnapshotOptions view_options(const CloseUpOptions& options) {
  SnapshotOptions snapshot;
  snapshot.width = snapshot.height = options.view_size;
  snapshot.samples_per_axis = options.samples_per_axis;
  return snapshot;
}

/// Whether `repaired` is `input` with faces appended, none of the input's marked new (as
/// the input's views show them); then `added` gets the faces after the input's.
bool appends_unmarked(const Mesh& input, const Mesh& repaired, std::vector<int>& added) {
  const KeptFaces kept = kept_faces(input, repaired);
  if (!kept.appends_to_input())
    return false;
  for (std::size_t f = 0; f < input.n_faces(); ++f) {
    if (is_new(repaired, repaired.face_handle(static_cast<int>(f))))
      return false;
  }
  added = kept.repaired_faces_not_kept;  // as a scene of the whole mesh holds them
  return true;
}

}  // namespace

Rgb kept_colour() {
  return shaded_grey();
}

Rgb open_hole_colour() {
  return {0.85f, 0.0f, 0.85f};
}

HoleView hole_view(const Case& c, std::size_t hole, const CloseUpOptions& options) {
  const RemovedSurface surface = removed_surface(c, hole);
  HoleView view;
  view.boundary_points = surface.boundary_points;
  const Point target = mean(surface.boundary_points);
  double radius = 0.0;
  for (const auto& p : surface.boundary_points)
    radius = std::max(radius, (p - target).norm());
  const double diagonal = bounding_box(c.complete).diagonal();
  radius = std::max(radius, 0.02 * diagonal);
  const embree::TriangleScene holed(c.input, embree::SceneBuild::fast_build);
  const double tolerance = options.visibility_tolerance_rel_diag * diagonal;
  bool first = true;
  for (const auto& direction : candidate_directions(surface)) {
    const Camera camera = frame_sphere(target, 1.5 * radius, direction, kFieldOfViewDegrees);
    const double share = visible_share(holed, camera, surface.boundary_points, tolerance);
    // A later candidate must show clearly more (the earlier ones face the missing surface).
    if (first || share > view.visible_share + 0.02) {
      view.camera = camera;
      view.visible_share = share;
      first = false;
    }
  }
  return view;
}

Camera whole_model_camera(const Case& c, const Point& direction) {
  const BoundingBox box = bounding_box(c.complete);
  return frame_sphere(box.center(), 0.5 * box.diagonal(), direction, kFieldOfViewDegrees);
}

Camera hole_or_whole_camera(const Case& c, std::size_t hole) {
  return hole < c.holes.size() ? hole_view(c, hole).camera
                               : whole_model_camera(c, Point(-1, -1, -1));
}

CasePicture::CasePicture(const Case& c, const CloseUpOptions& options)
    : complete_scene_(std::make_unique<embree::TriangleScene>(c.complete)),
      scale_(case_heat_scale(c)) {
  const std::size_t close_ups =
      std::min(c.holes.size(), static_cast<std::size_t>(std::max(0, options.max_close_ups)));
  for (std::size_t hole = 0; hole < close_ups; ++hole)
    hole_views_.push_back(hole_view(c, hole, options));
  whole_camera_ = whole_model_camera(
      c, hole_views_.empty() ? Point(-1, -1, -1) : hole_views_.front().camera.direction);
  if (!options.draw_over_input_views)
    return;
  const embree::TriangleScene input_scene(c.input);
  SnapshotOptions snapshot = view_options(options);
  snapshot.colouring = [](FaceHandle, const Point&) -> std::optional<Rgb> { return kept_colour(); };
  for (const auto& view : hole_views_)
    input_views_.push_back(input_view(c.input, input_scene, view.camera, snapshot));
  input_views_.push_back(input_view(c.input, input_scene, whole_camera_, snapshot));
}

CasePicture::~CasePicture() = default;

Image job_picture(const Case& c, const MethodResult& result, const CloseUpOptions& options) {
  // One picture: the input's views would cost more than they save.
  CloseUpOptions alone = options;
  alone.draw_over_input_views = false;
  return job_picture(c, result, CasePicture(c, alone), options);
}

Image job_picture(const Case& c, const MethodResult& result, const CasePicture& shared,
                  const CloseUpOptions& options) {
  const HeatScale& scale = shared.scale();
  const double diagonal = bounding_box(c.complete).diagonal();
  const embree::TriangleScene& truth = shared.complete_scene();
  const Mesh& mesh = result.repaired;
  SnapshotOptions snapshot = view_options(options);
  // Each patch face's nearby triangles of the complete model found once for its pixels: the
  // same distances as the scene's closest points (near_face_distance.h).
  embree::NearFaceDistance distances(mesh, truth);
  snapshot.colouring = [&](FaceHandle f, const Point& hit) -> std::optional<Rgb> {
    if (!is_new(mesh, f))
      return kept_colour();
    return heat_colour(distances.distance(f, hit) / diagonal, scale);
  };
  const Overlay overlay = job_overlay(c, result);

  std::vector<Camera> cameras;
  for (const auto& view : shared.hole_views())
    cameras.push_back(view.camera);
  cameras.push_back(shared.whole_camera());
  std::vector<Image> views;
  std::vector<int> added;
  if (shared.input_views().size() == cameras.size() && appends_unmarked(c.input, mesh, added)) {
    // The input's views with the repair's own faces traced over them.
    std::unique_ptr<embree::TriangleScene> added_scene;
    if (!added.empty())
      added_scene = std::make_unique<embree::TriangleScene>(mesh, added);
    for (const auto& input : shared.input_views())
      views.push_back(
          render_over_input_view(input, mesh, added, added_scene.get(), snapshot, overlay).image);
  } else {
    // One scene of the repaired mesh for every view.
    const embree::TriangleScene scene(mesh);
    for (const auto& camera : cameras)
      views.push_back(render_with_depth(mesh, scene, camera, snapshot, overlay).image);
  }

  const int gap = 4;
  const int width =
      static_cast<int>(views.size()) * (options.view_size + gap) + options.colour_bar_width;
  Image picture(width, options.view_size);
  fill(picture, {1, 1, 1});
  int x = 0;
  for (const auto& view : views) {
    paste(picture, view, x, 0);
    x += options.view_size + gap;
  }
  paste(picture, colour_bar(scale, options.colour_bar_width, options.view_size), x, 0);
  return picture;
}

}  // namespace holebench::render
