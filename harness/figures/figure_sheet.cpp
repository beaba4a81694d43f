#include "harness/figures/figure_sheet.h"

#include "core/atomic_file.h"
#include "core/split_text.h"
#include "harness/outputs/file_bytes.h"
#include "harness/outputs/render/bitmap_text.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/image.h"
#include "harness/results/markup_escape.h"

#include <fmt/format.h>

#include <algorithm>

namespace holebench::harness {

render::Image figure_sheet(const std::vector<FigurePanel>& panels, int columns, int label_height) {
  const int gap = 4;
  int cell_width = 1, cell_height = 1;
  for (const auto& p : panels) {
    cell_width = std::max(cell_width, p.image.width);
    cell_height = std::max(cell_height, p.image.height + label_height);
  }
  columns = std::max(1, std::min(columns, static_cast<int>(panels.size())));
  const int rows = std::max(1, (static_cast<int>(panels.size()) + columns - 1) / columns);
  render::Image sheet(columns * (cell_width + gap) - gap, rows * (cell_height + gap) - gap);
  render::fill(sheet, {1, 1, 1});
  for (std::size_t i = 0; i < panels.size(); ++i) {
    const int x = static_cast<int>(i) % columns * (cell_width + gap);
    const int y = static_cast<int>(i) / columns * (cell_height + gap);
    const std::string label = render::capitals(panels[i].label);
    render::TextOptions text;
    if (render::text_width(label, text) > cell_width - 8)
      text.scale = 1;
    render::draw_text(sheet, x + 4, y + (label_height - 7 * text.scale) / 2, label, text);
    render::paste(sheet, panels[i].image, x, y + label_height);
  }
  return sheet;
}

std::string figure_caption(const std::string& title, const std::vector<std::string>& lines,
                           const FigureProvenance& provenance) {
  std::string caption = title + "\n";
  for (const auto& line : lines)
    caption += line + "\n";
  caption += "code: holebench " + provenance.code_version + "\n";
  caption += "run: " + (provenance.run.empty() ? std::string("none") : provenance.run) + "\n";
  return caption;
}

bool wanted(const PaperFigureOptions& options, const std::string& stem) {
  return options.only.empty() ||
         std::find(options.only.begin(), options.only.end(), stem) != options.only.end();
}

void append(std::vector<std::filesystem::path>& files, std::vector<std::filesystem::path> more) {
  for (auto& f : more)
    files.push_back(std::move(f));
}

std::vector<std::filesystem::path> write_figure(const render::Image& sheet,
                                                const std::string& caption,
                                                const std::filesystem::path& stem) {
  auto png = stem, svg = stem, txt = stem;
  png += ".png";
  svg += ".svg";
  txt += ".txt";
  render::write_png(sheet, png);
  const std::vector<std::string> lines = split_text(caption, '\n');
  const int line_height = 16;
  const int height = sheet.height + 8 + line_height * static_cast<int>(lines.size());
  std::string text = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{0}\" height=\"{1}\" "
      "viewBox=\"0 0 {0} {1}\">\n<rect width=\"{0}\" height=\"{1}\" fill=\"white\"/>\n"
      "<image width=\"{0}\" height=\"{2}\" href=\"data:image/png;base64,{3}\"/>\n",
      sheet.width, height, sheet.height, base64(read_bytes(png)));
  for (std::size_t i = 0; i < lines.size(); ++i) {
    text += fmt::format(
        "<text x=\"4\" y=\"{}\" font-family=\"sans-serif\" font-size=\"12\">{}</text>\n",
        sheet.height + 4 + line_height * static_cast<int>(i + 1), xml_escape(lines[i]));
  }
  text += "</svg>\n";
  write_file_atomically(svg, text);
  write_file_atomically(txt, caption);
  return {png, svg, txt};
}

render::Image mesh_panel(const Mesh& mesh, const PanelView& view, const render::Overlay& overlay) {
  render::SnapshotOptions snapshot;
  snapshot.width = snapshot.height = view.size;
  snapshot.samples_per_axis = view.samples_per_axis;
  const bool regions = view.regions_coloured;
  const render::Rgb patch = view.patch_colour;
  snapshot.colouring = [&mesh, regions, patch](FaceHandle f,
                                               const Point&) -> std::optional<render::Rgb> {
    if (is_new(mesh, f))
      return patch;
    if (regions)
      return std::nullopt;
    return render::kept_colour();
  };
  return render::render_snapshot(mesh, view.camera, snapshot, overlay);
}

render::Camera tilted(const render::Camera& camera, double degrees) {
  const Point d = camera.direction / camera.direction.norm();
  // An axis perpendicular to the view: across the coordinate axis d is least aligned with.
  Point helper(0, 0, 0);
  int least = 0;
  for (int k = 1; k < 3; ++k) {
    if (std::abs(d[k]) < std::abs(d[least]))
      least = k;
  }
  helper[least] = 1.0;
  Point side = OpenMesh::cross(d, helper);
  side /= side.norm();
  const double angle = degrees * M_PI / 180.0;
  render::Camera out = camera;
  out.direction = d * std::cos(angle) + OpenMesh::cross(d, side) * std::sin(angle);
  return out;
}

render::Camera hole_camera(const Case& c, std::size_t hole, double zoom_out) {
  render::Camera camera = render::hole_or_whole_camera(c, hole);
  camera.distance *= zoom_out;
  return camera;
}

}  // namespace holebench::harness
