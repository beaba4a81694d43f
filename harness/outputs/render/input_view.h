// A view of a case's input kept sample by sample, so that each job draws only what its repair
// adds. A repair that appends to its input (every input face kept at its index, its own faces
// after them: metrics/kept_faces.h) shows, in every sample that misses its new faces or sees
// them behind the input, what the input alone shows there. So the picture of the repaired
// mesh is the kept view with the new faces traced over it, in the pixels their projection
// covers: the cost of the patch, not of the model.
#pragma once

#include "core/mesh.h"
#include "harness/outputs/render/snapshot.h"

#include <vector>

namespace holebench::embree {
class TriangleScene;
}

namespace holebench::render {

/// What a camera sees of a mesh M0 (a case's input), sample by sample, in the order of
/// primary_rays.
struct InputView {
  Camera camera;
  int samples_per_axis = 1;     ///< the size is the picture's
  std::vector<float> distance;  ///< per sample, the first hit's distance; infinity: none
  std::vector<Rgb> colour;      ///< per sample, its shaded colour (the background where none)
  Rendering picture{Image(0, 0), {}};  ///< M0 alone, without overlay: pixels and depth
};

/// The view of `mesh` from `camera`, its faces shaded as render_with_depth shades them with
/// `options` (size, supersampling, colouring). `scene`: an Embree scene of `mesh`.
InputView input_view(const Mesh& mesh, const embree::TriangleScene& scene, const Camera& camera,
                     const SnapshotOptions& options);

/// The picture of `mesh` (M0's faces, each at its index with its triangle, shaded in the view
/// as the view shades them, and `added`: the faces of `mesh` that are not M0's) with
/// `overlay`, drawn over `view`: render_with_depth's picture of `mesh` from the view's camera,
/// where every sample takes the nearer of M0's hit and the added faces' (M0's where both lie at
/// the same distance). `added_scene`: an Embree scene of `added` alone (nullptr when there are
/// none); `options`: the view's size and supersampling, the colouring of the added faces.
Rendering render_over_input_view(const InputView& view, const Mesh& mesh,
                                 const std::vector<int>& added,
                                 const embree::TriangleScene* added_scene,
                                 const SnapshotOptions& options, const Overlay& overlay = {});

}  // namespace holebench::render
