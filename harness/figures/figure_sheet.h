// The papers' figures as sheets of captioned panels (`holebench figures`): panels laid out in
// rows like the papers' (a), (b), ...; each figure written as a PNG, an SVG that holds the
// same picture and its caption as text, and a caption file naming the run, the code version
// and the cases. The same panels and caption give the same bytes.
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "harness/outputs/render/snapshot.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct FigurePanel {
  render::Image image;
  std::string label;  ///< drawn above the panel in capitals, e.g. "(a) input"
};

/// The panels in rows of `columns`, each under its label, on white with a 4-pixel gap.
/// Panels of different sizes take the largest's cell.
render::Image figure_sheet(const std::vector<FigurePanel>& panels, int columns,
                           int label_height = 22);

/// Writes `stem`.png, `stem`.svg (the PNG embedded, the caption's lines as text under it) and
/// `stem`.txt (the caption); returns the three paths.
std::vector<std::filesystem::path> write_figure(const render::Image& sheet,
                                                const std::string& caption,
                                                const std::filesystem::path& stem);

/// How a figure's panel shows a mesh: kept faces grey, new faces (the patch) in
/// `patch_colour` (the papers' red or green), over the camera's view.
struct PanelView {
  render::Camera camera;
  int size = 320;
  int samples_per_axis = 2;
  render::Rgb patch_colour{0.85f, 0.10f, 0.10f};
  bool regions_coloured = false;  ///< true: the input's region colours instead of grey
};
render::Image mesh_panel(const Mesh& mesh, const PanelView& view,
                         const render::Overlay& overlay = {});

/// render::hole_or_whole_camera(c, hole), its distance scaled by
/// `zoom_out` (> 1 shows more around the hole).
render::Camera hole_camera(const Case& c, std::size_t hole = 0, double zoom_out = 1.0);

/// What every figure's caption names besides its own content: this build's code version and
/// the run whose records the figure's tables read ("none" for pictures alone).
struct FigureProvenance {
  std::string code_version;
  std::string run;
};

/// A caption: the title, the figure's own lines (panels, cases, methods), then "code: ..." and
/// "run: ...", one per line.
std::string figure_caption(const std::string& title, const std::vector<std::string>& lines,
                           const FigureProvenance& provenance);

/// `camera` turned by `degrees` about its target (the axis perpendicular to the view and to
/// the coordinate axis the view is least aligned with): an oblique view of a hole seen
/// head-on.
render::Camera tilted(const render::Camera& camera, double degrees);

/// What every rendered paper figure is drawn with.
struct PaperFigureOptions {
  std::filesystem::path out_dir;
  int panel_size = 300;  ///< pixels of each square panel
  int samples_per_axis = 2;
  FigureProvenance provenance;
  /// Figures to write, by stem ("figure2", "figure12", ...); empty: all.
  std::vector<std::string> only;
};

/// Whether `options` asks for the figure `stem`.
bool wanted(const PaperFigureOptions& options, const std::string& stem);

/// Appends `more` to `files`.
void append(std::vector<std::filesystem::path>& files, std::vector<std::filesystem::path> more);

}  // namespace holebench::harness
