// Face provenance of an external method's output, recovered by matching its faces to the
// input's: every input face must come back unchanged (the same three vertex positions, bit
// for bit, in the same cyclic order, so with the same orientation; faces and vertices in any
// order); the output's other faces are the patch. A program that stores coordinates in
// single precision (MeshLab) is matched with a tolerance instead: an output vertex within
// it of an input vertex is that vertex, moved back to the input's position.
#pragma once

#include "core/mesh_builder.h"
#include "core/method_result.h"

#include <string>

namespace holebench {

struct OutputPatch {
  /// The input (same element indices, regions and provenance) plus the patch: new vertices
  /// (output vertices at no input vertex's position) and new faces, `Provenance::New`.
  Mesh repaired;
  std::size_t input_faces_missing = 0;  ///< input faces the output changed or dropped
  std::size_t new_faces = 0;            ///< patch faces added to `repaired`
  std::size_t refused_faces = 0;        ///< patch faces the mesh could not take (non-manifold)
  /// One report per boundary loop of the input: closed when no edge of the loop is boundary
  /// any more; new faces and vertices of the patch's connected parts that touch the loop.
  std::vector<HoleReport> holes;
};

/// Matches `output` to `holed`; `vertex_tolerance` (model units; 0: exact positions) is how
/// far an output vertex may lie from the input vertex it stands for. Throws InvalidInputError
/// for a non-finite coordinate or a vertex index out of range.
OutputPatch recover_output_patch(const Mesh& holed, const TriangleSoup& output,
                                 double vertex_tolerance = 0.0);

/// The method's result an output patch makes, for a repair whose program says no more than its
/// mesh (an external method, a repaired mesh scored from a file): the patch's hole reports; ok
/// when every hole is closed, failed when none is and no face was added, partial otherwise,
/// with a message that counts the open holes and the output's faces left out.
MethodResult result_of_output_patch(OutputPatch patch);

}  // namespace holebench
