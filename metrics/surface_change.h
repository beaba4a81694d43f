// How the surface B of a search differs from the B0 that bounds computed once per case were
// computed against (MeanCellBounds in surface_distance.h, HausdorffCellBounds in
// hausdorff_distance.h): a repair is the input away from its new faces, so the complete
// model's cells bounded against the input keep their bounds against the repair wherever what
// the bounds read of the input lies away from the repair's changes.
#pragma once

#include "metrics/cell_table.h"
#include "metrics/growing_box.h"
#include "metrics/triangle_cell.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace holebench {

struct SurfaceChange {
  /// By face of B, the face of B0 with the same triangle, or -1; nullptr: B is B0. Faces of
  /// both must be in the same order (a later face of B0 is a later face of B), so that ties
  /// between equally near faces, broken by the smaller index, break the same way.
  const std::vector<int>* b0_face_of_b = nullptr;
  /// The other way: by face of B0, the face of B with the same triangle, or -1 (set with
  /// b0_face_of_b; without it, answers against B0 are not taken for B).
  const std::vector<int>* b_face_of_b0 = nullptr;
  /// A box holding every face of B that B0 does not have and every face of B0 that B does
  /// not have.
  GrowingBox changed;
};

/// A cell of a search against B with its corners' nearest faces read as B0's
/// (`b0_face_of_b`), to look it up among cells bounded against B0; nullopt where one of them
/// is not a face of B0.
inline std::optional<TriangleCell> as_cell_of_b0(const TriangleCell& cell,
                                                 const std::vector<int>& b0_face_of_b) {
  TriangleCell as_b0 = cell;
  for (int& face : as_b0.corner_face) {
    if (face < 0 || static_cast<std::size_t>(face) >= b0_face_of_b.size() ||
        b0_face_of_b[static_cast<std::size_t>(face)] < 0)
      return std::nullopt;
    face = b0_face_of_b[static_cast<std::size_t>(face)];
  }
  return as_b0;
}

/// What `table` (cells bounded against B0, each value with the box `reach` of B0 its bounds
/// read) holds for `cell`, of face `face` of A, in a search against B: its value where B is
/// B0 (`change` null or without a face map), or where the cell's corners' nearest faces are
/// B0's and B's changes miss its reach; else null.
template <class Value>
const Value* find_against(const CellTable<Value>& table, const TriangleCell& cell, int face,
                          const SurfaceChange* change) {
  if (!change || !change->b0_face_of_b)
    return table.find(key_of(cell), face);
  const std::optional<TriangleCell> as_b0 = as_cell_of_b0(cell, *change->b0_face_of_b);
  if (!as_b0)
    return nullptr;
  const Value* recorded = table.find(key_of(*as_b0), face);
  return recorded && !recorded->reach.meets(change->changed) ? recorded : nullptr;
}

}  // namespace holebench
