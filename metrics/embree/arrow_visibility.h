// Quality of a guidance arrow (P, r) of the B-Rep paper (section 3.3) by Embree ray casts:
// is P outside the complete model, is the arrow's shaft free of it, and how much of the
// missing surface would a depth camera at P looking along r see?
//
// Definitions (lengths in model units):
//  - missing surface: the hole's removed faces of the complete model, sampled by splitting
//    each face into m x m similar sub-triangles (m = ceil(longest edge / sample_spacing),
//    at most max_subdivision) and taking their centroids, each weighted by its area;
//  - position outside: a ray from P crosses the (closed) complete model an even number of
//    times; three fixed, generic directions vote;
//  - shaft: the segment from P along r to where the ray first meets the missing surface,
//    or, if it misses it, to the projection of the missing surface's area centroid onto the
//    ray (the arrow points at the hole: eq. 3 of the paper puts P = T - d r). It is free
//    when the complete model does not intersect it before its end (less surface_tolerance
//    and the single precision of Embree's ray parameter, 1e-6 of |P|_1 + the shaft's length:
//    the end lies on the model, and a hit there is the end itself);
//  - a sample s with unit normal n (of the complete model) is seen from a camera at P along
//    a unit direction u when: the angle between s - P and u is at most half the field of
//    view; it faces the camera (n . (P - s) > 0); and the holed model does not occlude the
//    segment from s to P (ray cast from s, surface_tolerance at both ends);
//  - visible fraction: the weight of the samples seen along r over the weight of all;
//  - best direction: among r and `search_directions` directions on a Fibonacci sphere, the
//    largest visible fraction from P; direction error: the angle between r and the nearest
//    direction that attains it (0 when r attains it).
#pragma once

#include "core/mesh.h"
#include "core/method_result.h"

#include <vector>

namespace holebench::embree {

class TriangleScene;

struct ArrowVisibilityOptions {
  double field_of_view_degrees = 60.0;  ///< full opening angle of the camera's view cone
  double sample_spacing = 1e-2;         ///< model units (the evaluation scales by the diagonal)
  int max_subdivision = 16;             ///< at most m x m samples per face
  int search_directions = 4096;         ///< directions of the best-direction search
  double surface_tolerance = 1e-7;      ///< model units: ray offsets at surfaces
};

struct SurfaceSamples {
  std::vector<Point> points;
  std::vector<Point> normals;   ///< unit, the face's
  std::vector<double> weights;  ///< areas
  std::vector<int> faces;       ///< face index of each sample
};

/// Samples of the faces `faces` of `mesh`, as described above.
SurfaceSamples sample_faces(const Mesh& mesh, const std::vector<int>& faces,
                            const ArrowVisibilityOptions& options);

struct ArrowQuality {
  bool position_outside = false;
  bool shaft_free = false;
  double shaft_length = 0.0;
  double visible_fraction = 0.0;
  double best_visible_fraction = 0.0;
  double direction_error_deg = 0.0;
};

/// The quality of `arrow` for the missing surface `missing` (samples of the removed faces of
/// the complete model), with scenes of the complete and of the holed model.
ArrowQuality arrow_quality(const GuidanceArrow& arrow, const SurfaceSamples& missing,
                           const TriangleScene& complete_scene, const TriangleScene& holed_scene,
                           const ArrowVisibilityOptions& options = {});

/// The visible fraction alone, for a camera at `position` looking along `direction`.
double visible_fraction(const Point& position, const Point& direction,
                        const SurfaceSamples& missing, const TriangleScene& holed_scene,
                        const ArrowVisibilityOptions& options = {});

/// Whether `p` lies inside the closed surface of `scene` (parity of ray crossings, three
/// directions voting).
bool is_inside(const Point& p, const TriangleScene& scene, double surface_tolerance);

}  // namespace holebench::embree
