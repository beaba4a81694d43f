// Where the whole model's searches of a repair start (SearchStart), from what the case's jobs
// share, for a repair that appends to the input: every input face and vertex kept at its
// index, its new faces and vertices after them (KeptFaces::appends_to_input), as most hole
// fillers repair. Such a repair's faces are the input's, whose distances to the complete
// model the case knows, and its new faces; and the complete model differs, against the
// repair, from the complete model against the input only at the faces and vertices the new
// faces touch. So each search's first pass, its faces not on the other surface and its
// area are the case's, changed where the new faces change them: work in the size of the
// patch and of the faces away from the other surface (the hole region, or everywhere on a
// noisy input), not in the size of the model. The starts are the ones surface_distance()
// makes from the meshes (the same vertex answers, faces and area, bit for bit), so the
// numbers are the same.
#pragma once

#include "core/mesh.h"
#include "metrics/kept_faces.h"
#include "metrics/shared_faces.h"
#include "metrics/vertex_distances.h"

#include <optional>
#include <vector>

namespace holebench {

namespace embree {
class TriangleScene;
}

class AppendedRepairStarts {
 public:
  /// `input_pass`: the input's first pass against the complete model (first_pass());
  /// `input_shared`: the faces the input shares with the complete model
  /// (SharedFacesOfInput::of_input(): the maps a repair's shared faces start from).
  AppendedRepairStarts(const Mesh& input, const Mesh& complete, const FirstPass& input_pass,
                       const SharedFaces& input_shared);

  /// The start of the repair's search against the complete model (`complete_scene`), where
  /// `repaired_shared` is shared_faces(repaired, complete); nothing where the repair does not
  /// append to the input.
  std::optional<SearchStart> repaired_to_complete(
      const Mesh& repaired, const KeptFaces& kept, const SharedFaces& repaired_shared,
      const embree::TriangleScene& complete_scene) const;

  /// The start of the complete model's search against the repair (`repaired_scene`);
  /// `earlier`: the vertex answers surface_distance() would take (earlier_vertex_answers()
  /// of that search's first bounds). Nothing where the repair does not append to the input.
  std::optional<SearchStart> complete_to_repaired(const Mesh& complete, const Mesh& repaired,
                                                  const KeptFaces& kept,
                                                  const SharedFaces& repaired_shared,
                                                  const embree::TriangleScene& repaired_scene,
                                                  const EarlierVertexAnswer& earlier) const;

 private:
  std::size_t input_faces_ = 0;
  std::size_t input_vertices_ = 0;
  // The input against the complete model: its first pass, its faces not on the complete
  // model, its area.
  VertexDistances input_pass_;
  std::vector<int> input_unshared_faces_;
  double input_area_ = 0.0;
  // The complete model against the input: its vertices on faces it shares with the input
  // (distance zero, the shared face), the others, its faces not shared, its area.
  VertexDistances complete_marked_;
  std::vector<int> complete_unmarked_vertices_;
  std::vector<int> complete_unshared_faces_;
  double complete_area_ = 0.0;
};

}  // namespace holebench
