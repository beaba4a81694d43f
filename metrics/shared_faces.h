// Faces that two meshes share exactly: the same three points, bit for bit, in either
// orientation. The distance from such a face to the other surface is zero at every point,
// so the distance searches (hausdorff_distance.h, surface_distance.h) need no closest-point
// query there. A repaired model shares every face away from its holes with the complete
// model, so in an evaluation most faces are shared and only the hole region is searched.
#pragma once

#include "core/mesh.h"
#include "metrics/kept_faces.h"

#include <array>
#include <cstddef>
#include <memory>
#include <optional>
#include <vector>

namespace holebench {

struct SharedFaces {
  std::vector<int> b_face_of_a;  ///< by face index of A: the same face in B, or -1
  std::vector<int> a_face_of_b;  ///< by face index of B: the same face in A, or -1
  std::size_t count = 0;         ///< number of shared faces
  /// The vertex indices of each face of A and of B, by face index (as matched above; the
  /// reach below reuses them).
  std::vector<std::array<int, 3>> a_corners, b_corners;
};

SharedFaces shared_faces(const Mesh& a, const Mesh& b);

/// shared_faces(repair, b) from shared_faces(input, b), for repairs that keep the input: what
/// is known of the input and of B is built once (metrics/case_evaluation.h keeps it per case)
/// and each repair's faces after the input's are matched alone.
class SharedFacesOfInput {
 public:
  SharedFacesOfInput(const Mesh& input, const Mesh& b);
  ~SharedFacesOfInput();
  SharedFacesOfInput(const SharedFacesOfInput&) = delete;
  SharedFacesOfInput& operator=(const SharedFacesOfInput&) = delete;

  /// shared_faces(input, b).
  const SharedFaces& of_input() const;
  /// shared_faces(repaired, b), the same result, where `repaired`'s first faces are the
  /// input's at their indices (kept: input_face_of_repaired[f] == f for every input face f)
  /// and its first vertices the input's (kept.input_vertices_kept): A's faces are matched in
  /// index order, so the input's faces match as in the input, and only the faces after them
  /// are looked up. Nothing where the repair does not keep the input so. The result has the
  /// face maps and the count; its `a_corners` and `b_corners` are left empty (the evaluation
  /// reads only the maps; hausdorff_distance() computes its own).
  std::optional<SharedFaces> of_repair(const Mesh& repaired, const KeptFaces& kept) const;

 private:
  struct Index;
  std::unique_ptr<Index> index_;
};

/// The faces of B (sorted) that can hold a closest point of a point on A's faces not shared
/// with B. Every such point x has d(x, B) <= |x - s| for any vertex s of a shared face (s
/// is a point of B), so with R the largest distance from the box of the unshared faces to
/// the best such s, only B's faces whose boxes meet that box grown by R are needed. Empty
/// when A shares every face; every face of B when A shares none.
std::vector<int> faces_of_b_within_reach(const Mesh& a, const Mesh& b,
                                         const std::vector<int>& b_face_of_a);
/// The same with the faces' vertex indices already known (SharedFaces::a_corners, b_corners).
std::vector<int> faces_of_b_within_reach(const Mesh& a, const Mesh& b,
                                         const std::vector<int>& b_face_of_a,
                                         const std::vector<std::array<int, 3>>& a_corners,
                                         const std::vector<std::array<int, 3>>& b_corners);

}  // namespace holebench
