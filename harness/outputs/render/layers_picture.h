// A method's steps drawn (issue #24): its layers of intermediate geometry (core/method_layers.h)
// over the input, one panel per layer, then the repair; for `holebench run --layers` and the
// papers' step-by-step figures.
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "harness/outputs/render/snapshot.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench::render {

/// The colour of the `index`-th layer of a result (a fixed palette, apart from the patch's
/// orange and the kept faces' grey).
Rgb layer_colour(std::size_t index);

/// `layer` added to `overlay` in `colour`: points as dots, polylines as lines joining
/// consecutive points, a surface as a solid (shaded, it hides and is hidden by the mesh).
void add_layer(Overlay& overlay, const MethodLayer& layer, const Rgb& colour);

/// The layers of `result` named in `names`, each in layer_colour(its index in `names`);
/// names without a layer are skipped.
Overlay layers_overlay(const MethodResult& result, const std::vector<std::string>& names);

struct LayersPictureOptions {
  int view_size = 320;  ///< each panel is square, in pixels
  int samples_per_axis = 2;
  int columns = 4;
  int caption_height = 22;  ///< the strip above each panel with its caption
  /// The view of every panel; unset: hole_or_whole_camera(c) (close_up.h: the first hole's
  /// close-up, chosen from the ground truth, as pictures may).
  std::optional<Camera> camera;
};

/// One panel per layer of `result`, in its order: the input (the holed mesh) with that
/// layer drawn, captioned with the layer's name and size; then a last panel, the repaired
/// mesh with every point and polyline layer drawn, captioned "REPAIRED". A result without
/// layers gives the last panel alone.
Image layers_picture(const Case& c, const MethodResult& result,
                     const LayersPictureOptions& options = {});

/// The caption of a layer's panel: its name in capitals and its size, e.g. "SLICES (12)".
std::string layer_caption(const MethodLayer& layer);

}  // namespace holebench::render
