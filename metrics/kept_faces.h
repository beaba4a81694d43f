// The faces of a repair that are the input's own. Most hole fillers copy the input and add
// their patch; the evaluation then reuses, for these faces, what it knows of the input from
// the case (metrics/case_evaluation.h).
#pragma once

#include "core/mesh.h"
#include "metrics/growing_box.h"

#include <vector>

namespace holebench {

/// A face of the repaired mesh is kept when it has the vertex indices of an input face in the
/// same order (from the same first vertex), each vertex at the input's index with the input's
/// point, bit for bit. Then its triangle is the input face's, point for point.
struct KeptFaces {
  std::vector<int> repaired_face_of_input;  ///< by input face index: its repaired face, or -1
  std::vector<int> input_face_of_repaired;  ///< by repaired face index: its input face, or -1
  /// The kept faces are in the input's order (a later input face has a later repaired face),
  /// so that "the smallest face index" picks the same face in both meshes.
  bool order_kept = true;
  /// Every input vertex is a vertex of the repair at its index with its point, bit for bit
  /// (what the repair adds are vertices after the input's).
  bool input_vertices_kept = false;
  /// Every input face is kept at its own index (what the repair adds are faces after the
  /// input's).
  bool input_faces_in_place = false;
  /// The repaired faces that are not kept (input_face_of_repaired -1), in index order,
  /// deleted ones among them: where the repair differs, without a pass over the model.
  std::vector<int> repaired_faces_not_kept;
  /// The input faces the repair did not keep (repaired_face_of_input -1), in index order.
  std::vector<int> input_faces_not_kept;
  /// No input face is dropped: every input face is kept.
  bool every_input_face_kept() const { return input_faces_not_kept.empty(); }
  /// The repair is the input with faces and vertices appended: every input face and vertex
  /// kept at its index (what most hole fillers do).
  bool appends_to_input() const { return input_vertices_kept && input_faces_in_place; }
};

KeptFaces kept_faces(const Mesh& input, const Mesh& repaired);

/// A box holding every face of `repaired` that is not kept and every face of `input` that
/// `repaired` did not keep: where the two meshes differ (empty where they do not).
GrowingBox changed_faces_box(const Mesh& input, const Mesh& repaired, const KeptFaces& kept);

}  // namespace holebench
