// The distance of every vertex of a mesh A to a surface B: the first pass that the
// Hausdorff and the mean-distance searches share (evaluate it once, pass it to both).
//
// A vertex of a face that A shares exactly with B (shared_faces.h) is a point of B: its
// distance is zero without a query. Every other vertex is queried with an upper bound on
// its answer taken from its neighbours already done, d(v, B) <= d(u, B) + |v - u| (the
// distance is 1-Lipschitz), so that Embree's BVH only visits boxes near the answer. The
// bound changes the work, never the answer.
#pragma once

#include "core/mesh.h"
#include "metrics/embree/triangle_scene.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

struct VertexDistances {
  std::vector<double> distance;   ///< by vertex index
  std::vector<int> nearest_face;  ///< a face of B holding a closest point, by vertex index
  std::size_t queries = 0;
};

/// The distance of a vertex not known yet (in VertexDistances::distance while it is made).
constexpr double kUnknownVertexDistance = -1.0;

/// Marks the vertices of face `f` of A, which lies on face `match` of B: distance zero,
/// nearest face `match` (a vertex on several such faces keeps the last one marked).
void mark_vertices_on_shared_face(const Mesh& a, FaceHandle f, int match,
                                  VertexDistances& distances);

/// A closest-point answer found before for vertex `vertex` of A against B (by a search of
/// the same point against the same triangles near it): true with its distance and face, or
/// false. Called from several threads at once.
using EarlierVertexAnswer = std::function<bool(int vertex, double& distance, int& face)>;

/// `b_face_of_a` (optional): by face of A, the face of B it coincides with, or -1.
/// `earlier` (optional): answers taken instead of querying (the same answers, since a query's
/// answer depends only on the point and the triangles near it).
VertexDistances vertex_distances(const Mesh& a, const embree::TriangleScene& b_scene,
                                 const std::vector<int>* b_face_of_a = nullptr,
                                 const EarlierVertexAnswer& earlier = {});

/// What is already known about A against B, to skip the searches' first pass; every part
/// optional.
struct KnownDistances {
  const VertexDistances* vertices = nullptr;      ///< from vertex_distances(a, b_scene, ...)
  const std::vector<int>* b_face_of_a = nullptr;  ///< faces of A lying on B: skipped
  /// With `area`: the faces of A not lying on B, in index order (SearchStart), which the
  /// searches take as their cells instead of passing over every face of A.
  const std::vector<int>* unshared_faces = nullptr;
  double area = 0.0;  ///< with `unshared_faces`: A's area (SearchStart)
};

/// Where a directed search of A against B starts, for a caller that knows it without a pass
/// over every face of A (an appended repair: appended_repair_starts.h): A's vertex
/// distances as vertex_distances() gives them (with the queries they took), the faces of A
/// that do not lie on B in index order (the searches' first cells; the mean search leaves
/// out those without area) and A's area (its faces with area, summed in index order). The
/// searches give the same numbers from it as from A.
struct SearchStart {
  VertexDistances vertices;
  std::vector<int> unshared_faces;
  double area = 0.0;
};

/// A's vertex distances as a search starts: `known.vertices` where given, else computed now
/// into `computed` (with the queries they took, which the search counts; none where known).
const VertexDistances& vertex_distances(const Mesh& a, const embree::TriangleScene& b_scene,
                                        const KnownDistances& known, VertexDistances& computed);

/// The first pass of A against B, done once for the searches and first-bound tables that
/// share it (case_evaluation.h): the faces of A lying on B and the distances of A's
/// vertices.
struct FirstPass {
  std::vector<int> b_face_of_a;  ///< by face of A: the face of B it coincides with, or -1
  VertexDistances vertices;      ///< vertex_distances(a, b_scene, &b_face_of_a)
  /// By face of A not lying on B, the closest point of B to the centroid of its cell
  /// (face_cell(): the point both first-bound tables query first, the mean's and the
  /// Hausdorff distance's), asked once for both; face -1 for the faces lying on B. The
  /// answer does not depend on the upper bound a query is given, so each table takes it as
  /// its own query would have answered.
  std::vector<embree::ClosestPoint> centroid;
};

/// `b` is the mesh of `b_scene`.
FirstPass first_pass(const Mesh& a, const Mesh& b, const embree::TriangleScene& b_scene);

}  // namespace holebench
