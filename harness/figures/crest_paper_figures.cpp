#include "harness/figures/crest_paper_figures.h"

#include "generators/case_catalog.h"
#include "harness/figures/figure_run.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/layers_picture.h"

#include <fmt/format.h>

#include <algorithm>

namespace holebench::harness {

const std::vector<std::string>& crest_crease_cases() {
  static const std::vector<std::string> ids = {"crease/fandisk/1", "crease/fandisk/2",
                                               "crease/fandisk/3"};
  return ids;
}

const std::string& crest_concave_corner_case() {
  static const std::string id = "crease/fandisk/concave_corner";
  return id;
}

namespace {

const render::Rgb kGreen{0.10f, 0.65f, 0.15f};

PanelView panel_view(const PaperFigureOptions& options, const Case& c) {
  PanelView view;
  view.camera = hole_camera(c, 0, 1.4);
  view.size = options.panel_size;
  view.samples_per_axis = options.samples_per_axis;
  return view;
}

std::string status_suffix(const MethodResult& result) {
  return result.status == MethodStatus::Ok ? std::string()
                                           : std::string(" ") + to_string(result.status);
}

// One row of figure 10: the input with crest_feature's crest lines (3.2), then the results of
// the methods that only close the hole.
std::vector<FigurePanel> figure_10_row(const PaperFigureOptions& options, const Case& c) {
  PanelView view = panel_view(options, c);
  view.regions_coloured = true;
  const MethodResult crest = run_method_for_figure("crest_feature", c, "no_user", true);
  std::vector<FigurePanel> row = {
      {mesh_panel(c.input, view, render::layers_overlay(crest, {"crest_lines"})),
       "input, crest lines"}};
  view.regions_coloured = false;
  for (const char* method : {"cgal_triangulate", "liepa_cgal"}) {
    const MethodResult result = run_method_for_figure(method, c);
    row.push_back({mesh_panel(result.repaired, view), method + status_suffix(result)});
  }
  return row;
}

// crest_feature's result with `user`: the patch in green, its feature points and lines drawn.
FigurePanel crest_panel(const PaperFigureOptions& options, const Case& c, const std::string& user,
                        bool flat) {
  PanelView view = panel_view(options, c);
  view.patch_colour = flat ? render::kept_colour() : kGreen;
  const MethodResult result = run_method_for_figure("crest_feature", c, user, true);
  const render::Overlay overlay =
      flat ? render::Overlay{}
           : render::layers_overlay(result, {"feature_lines", "feature_points"});
  return {mesh_panel(result.repaired, view, overlay),
          fmt::format("{}{}{}", user == "no_user" ? "no user" : user, flat ? ", flat" : "",
                      status_suffix(result))};
}

std::vector<std::string> case_lines(const std::vector<std::string>& ids) {
  std::vector<std::string> lines;
  for (const auto& id : ids)
    lines.push_back(fmt::format("case: {} (noise 0 %, seed 0)", id));
  return lines;
}

std::vector<std::filesystem::path> figure_10(const PaperFigureOptions& options) {
  std::vector<FigurePanel> panels;
  for (const auto& id : crest_crease_cases()) {
    for (auto& panel : figure_10_row(options, generators::make_case(id)))
      panels.push_back(std::move(panel));
  }
  auto lines = case_lines(crest_crease_cases());
  lines.insert(lines.begin(),
               "rows: holes across 1, 2 and 3 creases of the fandisk; columns: the input with "
               "crest_feature's crest lines (section 3.2), cgal_triangulate and liepa_cgal "
               "(methods that only close the hole, as the paper's [12] and [19])");
  lines.push_back("methods: crest_feature (layers), cgal_triangulate, liepa_cgal (no_user)");
  return write_figure(figure_sheet(panels, 3),
                      figure_caption("Crest-line paper, figure 10: three crease holes of the "
                                     "fandisk, input and closing-only methods",
                                     lines, options.provenance),
                      options.out_dir / "figure10_crest_crease_holes");
}

std::vector<std::filesystem::path> figure_13(const PaperFigureOptions& options) {
  std::vector<FigurePanel> panels;
  for (const auto& id : crest_crease_cases()) {
    const Case c = generators::make_case(id);
    panels.push_back(crest_panel(options, c, "no_user", false));
    panels.push_back(crest_panel(options, c, "oracle", false));
    panels.push_back(crest_panel(options, c, "oracle", true));
  }
  auto lines = case_lines(crest_crease_cases());
  lines.insert(lines.begin(),
               "rows: holes across 1, 2 and 3 creases; columns: crest_feature with no user and "
               "with the oracle user (the patch in green, feature lines and points drawn), and "
               "the oracle's result flat shaded");
  lines.push_back("method: crest_feature (no_user, oracle; layers)");
  return write_figure(figure_sheet(panels, 3),
                      figure_caption("Crest-line paper, figure 13: the crease holes filled", lines,
                                     options.provenance),
                      options.out_dir / "figure13_crest_crease_holes_filled");
}

std::vector<std::filesystem::path> figure_12(const PaperFigureOptions& options) {
  const Case c = generators::make_case(crest_concave_corner_case());
  PanelView view = panel_view(options, c);
  view.regions_coloured = true;
  const MethodResult crest = run_method_for_figure("crest_feature", c, "no_user", true);
  std::vector<FigurePanel> panels = {
      {mesh_panel(c.input, view, render::layers_overlay(crest, {"crest_lines"})), "(a) input"},
      crest_panel(options, c, "no_user", false),
      crest_panel(options, c, "oracle", false),
      crest_panel(options, c, "oracle", true)};
  for (std::size_t i = 1; i < panels.size(); ++i)  // the caption's letters
    panels[i].label = fmt::format("({}) {}", static_cast<char>('a' + i), panels[i].label);
  auto lines = case_lines({crest_concave_corner_case()});
  lines.insert(lines.begin(),
               "(a) the input with its crest lines; (b) crest_feature with no user and (c) with "
               "the oracle user, the patch in green; (d) the oracle's result flat shaded");
  lines.push_back("method: crest_feature (no_user, oracle; layers)");
  return write_figure(figure_sheet(panels, 4),
                      figure_caption("Crest-line paper, figure 12: a concave corner hole of "
                                     "the fandisk",
                                     lines, options.provenance),
                      options.out_dir / "figure12_crest_concave_corner");
}

}  // namespace

std::vector<std::filesystem::path> write_crest_paper_figures(const PaperFigureOptions& options) {
  std::vector<std::filesystem::path> files;
  if (wanted(options, "figure10"))
    append(files, figure_10(options));
  if (wanted(options, "figure12"))
    append(files, figure_12(options));
  if (wanted(options, "figure13"))
    append(files, figure_13(options));
  return files;
}

}  // namespace holebench::harness
