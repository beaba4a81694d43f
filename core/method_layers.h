// A method's steps as geometry (issue #24): named layers of intermediate geometry a method
// may return with its result, so that a researcher sees where it went wrong and the papers'
// step-by-step figures can be drawn. Metrics ignore them; the renderer draws them
// (harness/outputs/render/layers_picture.h). Methods fill them only when asked
// (MethodParameters::record_layers): off in suite runs, on for figures and `--layers`.
#pragma once

#include "core/mesh.h"
#include "core/mesh_builder.h"

#include <string>
#include <vector>

namespace holebench {

/// What a layer holds: points (feature points, a corner), polylines (segments, traced
/// edges, section curves, sub-hole loops, arrows) or a surface (a lofted surface sampled as
/// triangles).
enum class LayerKind { Points, Polylines, Surface };
const char* to_string(LayerKind kind);

struct MethodLayer {
  std::string name;  ///< snake_case, e.g. "section_curves"
  std::string step;  ///< the paper's step it shows, as in the method's phase names
  LayerKind kind = LayerKind::Points;
  std::vector<Point> points;                  ///< LayerKind::Points
  std::vector<std::vector<Point>> polylines;  ///< LayerKind::Polylines: open, in order
  TriangleSoup surface;                       ///< LayerKind::Surface

  /// Points, polylines or triangles, by kind.
  std::size_t size() const;
};

/// The layer named `name` in `layers`, created with `step` and `kind` at the end if absent:
/// a method that runs a step once per hole adds every hole's geometry to one layer. Creating
/// a layer may move the others: fill one before looking up the next.
MethodLayer& layer_named(std::vector<MethodLayer>& layers, const std::string& name,
                         const std::string& step, LayerKind kind);

/// Appends each layer of `from` to the layer of the same name in `into` (created at the end
/// if absent): the layers of one hole added to those of the holes before it.
void append_layers(std::vector<MethodLayer>& into, std::vector<MethodLayer> from);

/// Appends the new faces of `mesh` (the patch: Provenance::New) to a surface layer, their
/// points copied.
void append_new_faces(MethodLayer& layer, const Mesh& mesh);

}  // namespace holebench
