// Snapshots of a mesh by Embree ray casting: one primary ray per sample, headlight
// Lambert shading, a colour per region, the patch (new faces) in a distinct colour and
// back faces (seen through a hole) dark.
#pragma once

#include "core/mesh.h"
#include "core/mesh_builder.h"
#include "harness/outputs/render/image.h"

#include <functional>
#include <optional>
#include <vector>

namespace holebench::embree {
class TriangleScene;
}

namespace holebench::render {

struct Camera {
  Point target{0.0, 0.0, 0.0};      ///< the point the camera looks at
  Point direction{0.0, 0.0, -1.0};  ///< viewing direction (from the camera to the target)
  double distance = 1.0;            ///< camera distance from the target
  double field_of_view_degrees = 40.0;
};

/// The base colour of a mesh face at a hit point, in place of its region or patch colour;
/// std::nullopt keeps that colour.
using FaceColouring = std::function<std::optional<Rgb>(FaceHandle face, const Point& hit)>;

struct SnapshotOptions {
  int width = 480;
  int height = 360;
  int samples_per_axis = 2;  ///< supersampling: samples_per_axis^2 rays per pixel
  FaceColouring colouring;   ///< empty: region colours, the patch orange
};

/// A camera looking along `direction` at `target` from just far enough that a sphere of
/// `radius` around the target fills the view.
Camera frame_sphere(const Point& target, double radius, const Point& direction,
                    double field_of_view_degrees = 40.0);

/// Lines and dots drawn over the shaded mesh where they are not hidden by it (a depth test
/// against the first hit of each pixel, with a tolerance so that lines on the surface show).
struct OverlayLine {
  Point a, b;
  Rgb colour;
  float width_px = 2.0f;
};
struct OverlayDot {
  Point p;
  Rgb colour;
  float radius_px = 4.0f;
};
/// A closed solid drawn into the scene in one colour, shaded like the mesh (it hides the
/// mesh and is hidden by it): the guidance arrows.
struct OverlaySolid {
  TriangleSoup triangles;
  Rgb colour;
};
struct Overlay {
  std::vector<OverlayLine> lines;
  std::vector<OverlayDot> dots;
  std::vector<OverlaySolid> solids;
};

/// A 3D arrow from `from` to `to` as a closed solid of revolution (a round shaft and a cone
/// for its head, `segments` around): shaft radius `radius`, head radius 2.5 radius and
/// length a quarter of the arrow's.
TriangleSoup arrow_solid(const Point& from, const Point& to, double radius, int segments = 20);

Image render_snapshot(const Mesh& mesh, const Camera& camera, const SnapshotOptions& options = {},
                      const Overlay& overlay = {});

/// A picture with its depth buffer: per pixel the smallest distance from the eye to what a
/// sample of the pixel hit (the mesh or an overlay solid), infinity where all missed.
struct Rendering {
  Image image;
  std::vector<double> depth;  ///< row-major, top row first

  double depth_at(int x, int y) const {
    return depth[static_cast<std::size_t>(y) * image.width + x];
  }
};

/// render_snapshot, keeping the depth buffer.
Rendering render_with_depth(const Mesh& mesh, const Camera& camera,
                            const SnapshotOptions& options = {}, const Overlay& overlay = {});
/// The same with the mesh's Embree scene built by the caller (once for several views; a
/// scene of `mesh` itself, SceneBuild::fast_queries: the same picture).
Rendering render_with_depth(const Mesh& mesh, const embree::TriangleScene& scene,
                            const Camera& camera, const SnapshotOptions& options = {},
                            const Overlay& overlay = {});

/// Where a point lands in a picture of `width` x `height` taken by `camera`.
struct Projection {
  double x = 0.0, y = 0.0;  ///< pixel coordinates (may lie outside the image)
  double depth = 0.0;       ///< distance from the eye
};
/// The projection of `p`, or std::nullopt when it lies behind the camera.
std::optional<Projection> project(const Camera& camera, int width, int height, const Point& p);

/// The camera's eye (target - direction * distance).
Point eye_of(const Camera& camera);

/// The primary rays a snapshot casts: from the camera's eye, samples_per_axis^2 per pixel,
/// pixel by pixel, row by row (the directions are not of unit length). For benchmarks that
/// compare the renderer with raw ray casting on the same rays.
struct PrimaryRays {
  Point eye;
  std::vector<Point> directions;
};
PrimaryRays primary_rays(const Camera& camera, const SnapshotOptions& options = {});

/// The colour of region `id` (a fixed palette, the same in every picture).
Rgb region_colour(int id);
/// The colour of new faces (the patch).
Rgb patch_colour();

}  // namespace holebench::render
