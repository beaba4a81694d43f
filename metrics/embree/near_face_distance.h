// Distances to a scene's surface from many points on the faces of another mesh, as the
// pixels of a picture of a patch coloured by its distance to the complete model ask for them
// (hundreds of points per face).
//
// Each face's candidate triangles of the scene are found once, at its first point: every
// triangle within d(g) + 2 R of its centroid g (R: the face's radius), with its distance
// from g. A point p of the face then takes the smallest distance to the candidates, nearest
// to g first, and stops where no farther candidate can be nearer: dist(p, T) >=
// dist(g, T) - |p - g|. The answer is TriangleScene::closest_point(p).distance, bit for bit
// (the same expression on the same triangles): p's nearest triangle lies within |p - g| +
// d(p) of g, which is checked for every point (with a margin far above rounding); where it
// fails, or where a face has too many candidates to be cheaper than the scene's BVH, the
// scene answers (with an upper bound from the last point answered, d being 1-Lipschitz).
#pragma once

#include "core/mesh.h"

#include <array>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace holebench::embree {

class TriangleScene;

struct NearFaceDistanceOptions {
  /// A face with more candidate triangles than this asks the scene for each point.
  std::size_t max_candidates = 256;
};

class NearFaceDistance {
 public:
  /// `mesh`: the mesh whose faces the points lie on; `scene`: the surface measured to.
  /// Both must outlive this.
  NearFaceDistance(const Mesh& mesh, const TriangleScene& scene,
                   const NearFaceDistanceOptions& options = {});

  /// d(p, scene) for a point p on face `f` of the mesh (or within rounding of it).
  double distance(FaceHandle f, const Point& p);

  /// Points answered from their face's candidates, and by the scene.
  std::size_t local_answers() const { return local_answers_; }
  std::size_t scene_answers() const { return scene_answers_; }

 private:
  struct Candidate {
    double from_centre = 0.0;  // dist(g, T)
    const std::array<Point, 3>* triangle = nullptr;
  };
  struct FaceCandidates {
    bool made = false;
    bool usable = false;  // false: the scene answers this face's points
    Point centre{0.0, 0.0, 0.0};
    double radius = 0.0;                // every triangle within this of the centre is a candidate
    double margin = 0.0;                // above the rounding of distances among the candidates
    std::vector<Candidate> candidates;  // by from_centre
  };
  void make(FaceHandle f, FaceCandidates& face) const;
  void remember(const Point& p, double distance) {
    last_ = true;
    last_point_ = p;
    last_distance_ = distance;
  }

  const Mesh& mesh_;
  const TriangleScene& scene_;
  NearFaceDistanceOptions options_;
  /// By face index, made at the face's first point: a picture asks about its patch's faces
  /// only, so nothing is held (or allocated) for the rest of the mesh.
  std::unordered_map<int, FaceCandidates> faces_;
  std::size_t local_answers_ = 0;
  std::size_t scene_answers_ = 0;
  bool last_ = false;
  Point last_point_{0.0, 0.0, 0.0};
  double last_distance_ = 0.0;
};

}  // namespace holebench::embree
