// An Embree 3 scene of a mesh's triangles, built once and queried many times: closest
// points (rtcPointQuery) and ray casts (rtcIntersect1 / rtcOccluded1).
//
// Embree stores single-precision vertices for its BVH; this class keeps the triangles in
// double precision and computes every distance and intersection parameter it returns in
// double. Culling in the BVH is single precision (about 1e-7 of the coordinates' size).
#pragma once

#include "core/mesh.h"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <vector>

struct RTCDeviceTy;
struct RTCSceneTy;

namespace holebench::embree {

struct ClosestPoint {
  Point point{0.0, 0.0, 0.0};
  double distance = 0.0;
  int face = -1;  ///< face index in the mesh the scene was built from
};

struct RayHit {
  bool hit = false;
  double distance = 0.0;  ///< ray parameter t (the direction is normalised)
  int face = -1;
  Point normal{0.0, 0.0, 0.0};  ///< unit geometric normal of the face hit (its orientation)
};

/// How Embree builds the BVH. Answers are the same either way (closest points break ties by
/// face index); only the time to build and to query changes.
enum class SceneBuild {
  fast_queries,  ///< Embree's default (binned SAH): the faster queries, for scenes queried a lot
  fast_build,    ///< Embree's low quality (Morton codes): about 2.5x faster to build, queries
                 ///< about 10 % slower; for scenes built for a few thousand queries
};

/// The single-precision rounding of a query about a point whose coordinates sum in absolute
/// value to `coordinate_sum`, at a distance `distance` along or from it: Embree's boxes, query
/// point and ray parameters are floats (about 6e-8 of their size), padded here to 1e-6 so that
/// no triangle within a radius is culled and a hit where a segment ends on a surface is taken
/// as its end.
inline double single_precision_pad(double coordinate_sum, double distance) {
  return 1e-6 * (coordinate_sum + distance);
}

/// |x| + |y| + |z| of `p`: the scale of its single-precision rounding.
inline double coordinate_sum(const Point& p) {
  return std::abs(p[0]) + std::abs(p[1]) + std::abs(p[2]);
}

class TriangleScene {
 public:
  /// A scene of the mesh's faces (those deleted and not yet collected left out). The scene
  /// keeps a reference to `mesh` (mesh()): the mesh must outlive the scene where mesh() is
  /// read (the Hausdorff search reads its connectivity).
  explicit TriangleScene(const Mesh& mesh, SceneBuild build = SceneBuild::fast_queries);
  /// A scene of some of the mesh's faces only (face indices of `mesh`; answers still name
  /// the mesh's face indices).
  TriangleScene(const Mesh& mesh, const std::vector<int>& faces,
                SceneBuild build = SceneBuild::fast_queries);
  /// A scene of `mesh` made of a scene `base` of another mesh whose faces `mesh` has too, and
  /// a scene of `mesh`'s other faces (`added`, face indices of `mesh`): a repair's scene from
  /// its input's (built once per case) and its patch's, at the cost of the patch. Every face
  /// of `base` must be in `mesh` (`face_of_base_face`: by base face, the face of `mesh` with
  /// the same triangle, corner for corner; `base_face_of_face`: the other way, or -1), in the
  /// same order (a later base face is a later face), and `added` must be every other face of
  /// `mesh`. Then every answer is the one a scene of the whole `mesh` gives: the same nearest
  /// triangle (the smallest face index among equals), the same faces within a radius. `base`,
  /// the two maps and `mesh` (where mesh() is read) must outlive the scene.
  TriangleScene(const TriangleScene& base, const std::vector<int>& face_of_base_face,
                const std::vector<int>& base_face_of_face, const Mesh& mesh,
                const std::vector<int>& added, SceneBuild build = SceneBuild::fast_queries);
  ~TriangleScene();
  TriangleScene(const TriangleScene&) = delete;
  TriangleScene& operator=(const TriangleScene&) = delete;

  /// The closest point of the mesh to `p`. Among faces at the same distance the one with
  /// the smallest index wins, so the answer does not depend on the BVH's layout.
  ClosestPoint closest_point(const Point& p) const;

  /// The same, given an upper bound on the distance (for example d(q) + |p - q| for a point
  /// q whose distance is known: the distance is 1-Lipschitz). The BVH then only visits
  /// boxes within the bound, which makes nearby queries several times cheaper. The answer
  /// is the same as without the bound (as long as the bound holds).
  ClosestPoint closest_point(const Point& p, double distance_upper_bound) const;

  /// Every face within `radius` of `p`, by face index: those whose point_triangle_distance()
  /// (core/distances.h, in double precision) is at most `radius`.
  std::vector<int> faces_within(const Point& p, double radius) const;

  /// The same, or nothing when more than `max_faces` faces are within `radius` (the search
  /// stops there: a caller that only wants a few nearby faces pays for no more).
  std::optional<std::vector<int>> faces_within(const Point& p, double radius,
                                               std::size_t max_faces) const;

  /// The first face a ray from `origin` along `direction` hits within (t_near, t_far).
  RayHit intersect(const Point& origin, const Point& direction, double t_near = 0.0,
                   double t_far = std::numeric_limits<double>::infinity()) const;

  /// intersect() for many rays from one origin (a camera's primary rays), as one stream that
  /// Embree traces as coherent rays: the same hits, faster. hits[i] is the first face along
  /// directions[i] (not necessarily unit); `hits` is resized to the rays' count.
  void intersect_coherent(const Point& origin, const std::vector<Point>& directions,
                          std::vector<RayHit>& hits) const;

  /// Whether anything blocks the ray within (t_near, t_far).
  bool occluded(const Point& origin, const Point& direction, double t_near = 0.0,
                double t_far = std::numeric_limits<double>::infinity()) const;

  /// The triangle of `face` (the mesh's face index) as three points.
  const std::array<Point, 3>& triangle_of_face(int face) const;
  /// The mesh the scene was built from (for a scene made of a base and an added one, the
  /// mesh given with them), with every face, whether or not the scene holds it.
  const Mesh& mesh() const { return *mesh_; }

  std::size_t triangle_count() const;

  /// A scene made of a base scene and an added one (the constructor from a base): the base,
  /// else nullptr.
  const TriangleScene* base_part() const { return base_; }
  /// A scene made of a base scene and an added one: the added one (nullptr where nothing was
  /// added, or for a scene built from faces).
  const TriangleScene* added_part() const { return added_.get(); }
  /// The triangles of a scene built from faces, in primitive order (empty for a scene made of
  /// parts).
  const std::vector<std::array<Point, 3>>& triangles() const { return triangles_; }

 private:
  /// The nearest triangle among those within `distance_upper_bound` (padded past it by the
  /// single-precision rounding), or face -1 and an infinite distance where there is none.
  ClosestPoint nearest_within(const Point& p, double distance_upper_bound) const;

  const Mesh* mesh_ = nullptr;
  RTCDeviceTy* device_ = nullptr;
  RTCSceneTy* scene_ = nullptr;
  std::vector<std::array<Point, 3>> triangles_;  // by Embree primitive id
  std::vector<int> face_of_primitive_;
  std::vector<int> primitive_of_face_;
  // A scene made of a base scene and an added one (the constructor from a base): queries
  // ask both and answer with `mesh`'s face indices.
  const TriangleScene* base_ = nullptr;
  const std::vector<int>* face_of_base_face_ = nullptr;
  const std::vector<int>* base_face_of_face_ = nullptr;
  std::unique_ptr<TriangleScene> added_;
};

}  // namespace holebench::embree
