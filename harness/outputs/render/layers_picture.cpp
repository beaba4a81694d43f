#include "harness/outputs/render/layers_picture.h"

#include "core/geometry.h"
#include "harness/outputs/render/bitmap_text.h"
#include "harness/outputs/render/close_up.h"

#include <fmt/format.h>

#include <algorithm>

namespace holebench::render {

Rgb layer_colour(std::size_t index) {
  static const Rgb palette[] = {
      {0.05f, 0.35f, 0.85f},  // blue
      {0.80f, 0.05f, 0.10f},  // red
      {0.05f, 0.60f, 0.20f},  // green
      {0.55f, 0.10f, 0.70f},  // purple
      {0.00f, 0.60f, 0.65f},  // teal
      {0.75f, 0.55f, 0.00f},  // ochre
      {0.85f, 0.20f, 0.60f},  // pink
      {0.10f, 0.10f, 0.10f},  // black
  };
  return palette[index % (sizeof(palette) / sizeof(palette[0]))];
}

void add_layer(Overlay& overlay, const MethodLayer& layer, const Rgb& colour) {
  switch (layer.kind) {
    case LayerKind::Points:
      for (const auto& p : layer.points)
        overlay.dots.push_back({p, colour, 4.0f});
      break;
    case LayerKind::Polylines:
      for (const auto& line : layer.polylines) {
        for (std::size_t i = 0; i + 1 < line.size(); ++i)
          overlay.lines.push_back({line[i], line[i + 1], colour, 2.0f});
        if (line.size() == 1)
          overlay.dots.push_back({line.front(), colour, 3.0f});
      }
      break;
    case LayerKind::Surface:
      if (!layer.surface.triangles.empty())
        overlay.solids.push_back({layer.surface, colour});
      break;
  }
}

Overlay layers_overlay(const MethodResult& result, const std::vector<std::string>& names) {
  Overlay overlay;
  for (std::size_t i = 0; i < names.size(); ++i) {
    for (const auto& layer : result.layers) {
      if (layer.name == names[i])
        add_layer(overlay, layer, layer_colour(i));
    }
  }
  return overlay;
}

std::string layer_caption(const MethodLayer& layer) {
  return fmt::format("{} ({})", capitals(layer.name), layer.size());
}

namespace {

Image captioned(const Image& view, const std::string& caption, int caption_height) {
  Image panel(view.width, view.height + caption_height);
  fill(panel, {1, 1, 1});
  TextOptions text;
  text.scale = 2;
  // Long captions drop to the small scale rather than run out of the panel.
  if (text_width(caption, text) > view.width - 8)
    text.scale = 1;
  draw_text(panel, 4, (caption_height - 7 * text.scale) / 2, caption, text);
  paste(panel, view, 0, caption_height);
  return panel;
}

}  // namespace

Image layers_picture(const Case& c, const MethodResult& result,
                     const LayersPictureOptions& options) {
  const Camera camera = options.camera ? *options.camera : hole_or_whole_camera(c);
  SnapshotOptions snapshot;
  snapshot.width = snapshot.height = options.view_size;
  snapshot.samples_per_axis = options.samples_per_axis;

  std::vector<Image> panels;
  Overlay all_lines;  // every point and polyline layer, for the last panel
  for (std::size_t i = 0; i < result.layers.size(); ++i) {
    const MethodLayer& layer = result.layers[i];
    Overlay overlay;
    add_layer(overlay, layer, layer_colour(i));
    if (layer.kind != LayerKind::Surface)
      add_layer(all_lines, layer, layer_colour(i));
    panels.push_back(captioned(render_snapshot(c.input, camera, snapshot, overlay),
                               layer_caption(layer), options.caption_height));
  }
  panels.push_back(captioned(render_snapshot(result.repaired, camera, snapshot, all_lines),
                             "REPAIRED", options.caption_height));

  const int gap = 4;
  const int columns = std::max(1, std::min(options.columns, static_cast<int>(panels.size())));
  const int rows = (static_cast<int>(panels.size()) + columns - 1) / columns;
  const int panel_height = options.view_size + options.caption_height;
  Image sheet(columns * (options.view_size + gap) - gap, rows * (panel_height + gap) - gap);
  fill(sheet, {1, 1, 1});
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    paste(sheet, panels[i], column * (options.view_size + gap), row * (panel_height + gap));
  }
  return sheet;
}

}  // namespace holebench::render
