#include "harness/figures/slice_paper_figures.h"

#include "core/geometry.h"
#include "generators/case_catalog.h"
#include "harness/figures/figure_run.h"
#include "harness/outputs/render/layers_picture.h"
#include "harness/results/markup_escape.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <map>

namespace holebench::harness {

const std::vector<SliceTable2Model>& slice_table_2_models() {
  // The paper's Table 2 ("Experimental results"); the errors are its columns "Error*E-03".
  static const std::vector<SliceTable2Model> models = {
      {"Figure 17", "a multi-segment corner hole (three regions) in a block",
       "solid/l_block/corner_ccc/large", 4372, 220, 44.017, 49.675},
      {"Figure 18", "a hole across two regions of a helical sweep of a square cross section",
       "solid/helical_sweep/edge_convex/small", 47090, 52, 3.017, 5.213},
      {"Figure 19", "a hole with an island", "solid/l_block/island/large", 25667, 87, 0.063, 0.094},
      {"Figure 20", "a hole in a gear tooth (CGAL's pinion)", "cad/pinion/gear_tooth/small", 16180,
       48, 30.407, 82.636},
  };
  return models;
}

const std::string& slice_cone_apex_case() {
  static const std::string id = "solid/cone/cone_apex/small";
  return id;
}

namespace {

PanelView panel_view(const PaperFigureOptions& options, const render::Camera& camera) {
  PanelView view;
  view.camera = camera;
  view.size = options.panel_size;
  view.samples_per_axis = options.samples_per_axis;
  return view;
}

std::string case_line(const Case& c) {
  return fmt::format("case: {} (noise {} %, seed {})", c.id, c.noise_percent, c.seed);
}

// Figure 2: the method's steps, one panel per layer, on the corner hole of figure 17.
std::vector<std::filesystem::path> figure_2(const PaperFigureOptions& options) {
  const Case c = generators::make_case(slice_table_2_models()[0].case_id);
  const MethodResult result = run_method_for_figure("slice_loft", c, "no_user", true);
  render::LayersPictureOptions layers;
  layers.view_size = options.panel_size;
  layers.samples_per_axis = options.samples_per_axis;
  layers.columns = 4;
  std::vector<std::string> names;
  for (const auto& layer : result.layers)
    names.push_back(fmt::format("{} ({})", layer.name, layer.step));
  return write_figure(
      render::layers_picture(c, result, layers),
      figure_caption("Slice paper, figure 2: the algorithm step by step (slice_loft's layers)",
                     {fmt::format("panels, over the input: {}; then the repaired mesh",
                                  fmt::join(names, "; ")),
                      case_line(c), "method: slice_loft (no_user)"},
                     options.provenance),
      options.out_dir / "figure2_slice_steps");
}

// Figures 17-20: per Table 2 model, (a) the input with its hole, (b) slice_loft's patch in
// red, (c) slice_direct's (the paper's comparison).
std::vector<std::filesystem::path> model_figure(const PaperFigureOptions& options,
                                                const SliceTable2Model& model) {
  const Case c = generators::make_case(model.case_id);
  PanelView view = panel_view(options, hole_camera(c, 0, 1.3));
  std::vector<FigurePanel> panels;
  view.regions_coloured = true;
  panels.push_back({mesh_panel(c.input, view), "(A) INPUT"});
  view.regions_coloured = false;
  for (const char* method : {"slice_loft", "slice_direct"}) {
    const MethodResult result = run_method_for_figure(method, c);
    std::string label = fmt::format("({}) {}", panels.size() == 1 ? 'B' : 'C', method);
    if (result.status != MethodStatus::Ok)
      label += std::string(" ") + to_string(result.status);
    panels.push_back({mesh_panel(result.repaired, view), label});
  }
  const std::string number = model.figure.substr(model.figure.find(' ') + 1);
  return write_figure(
      figure_sheet(panels, 3),
      figure_caption(fmt::format("Slice paper, {}: {}", model.figure, model.what),
                     {"(a) the input with its hole (regions coloured); (b) slice_loft's patch "
                      "in red; (c) slice_direct's (the paper's Table 2 comparison)",
                      case_line(c), "methods: slice_loft, slice_direct (no_user)"},
                     options.provenance),
      options.out_dir / fmt::format("figure{}_slice_model", number));
}

// Figure 22: the patch of figure 17's hole under 5 % and 25 % noise.
std::vector<std::filesystem::path> figure_22(const PaperFigureOptions& options) {
  const std::string& id = slice_table_2_models()[0].case_id;
  std::vector<FigurePanel> panels;
  std::vector<std::string> lines = {
      "(a) 5 % noise, (b) 25 % noise (of 1 % of the diagonal): "
      "slice_loft's patch in red"};
  // One camera for both panels: the clean case's view of the hole.
  const render::Camera camera = hole_camera(generators::make_case(id), 0, 1.3);
  for (double noise : {5.0, 25.0}) {
    const Case c = generators::make_case(id, 0, noise);
    const MethodResult result = run_method_for_figure("slice_loft", c);
    panels.push_back({mesh_panel(result.repaired, panel_view(options, camera)),
                      fmt::format("({}) NOISE {} %", panels.empty() ? 'A' : 'B', noise)});
    lines.push_back(case_line(c));
  }
  lines.push_back("method: slice_loft (no_user)");
  return write_figure(
      figure_sheet(panels, 2),
      figure_caption("Slice paper, figure 22: the patch under noise", lines, options.provenance),
      options.out_dir / "figure22_slice_noise");
}

// Figures 23 and 24: the cone with its apex missing: (23a) the input, (23b) its top view,
// (23c) the slices around the apex; (24a) the recovered apex (the lofted surface and the
// section curves), (24b) the final output.
std::vector<std::filesystem::path> figures_23_24(const PaperFigureOptions& options) {
  const Case c = generators::make_case(slice_cone_apex_case());
  const MethodResult result = run_method_for_figure("slice_loft", c, "no_user", true);
  // The hole is seen head-on from above the apex (the top view); the other panels look at it
  // obliquely, so that the cone's shape shows.
  const render::Camera top = hole_camera(c, 0, 2.5);
  const render::Camera close = tilted(hole_camera(c, 0, 2.0), 55.0);
  PanelView view = panel_view(options, close);
  view.regions_coloured = true;
  std::vector<FigurePanel> panels23 = {{mesh_panel(c.input, view), "(A) INPUT"}};
  view.camera = top;
  panels23.push_back({mesh_panel(c.input, view), "(B) TOP VIEW"});
  view.camera = close;
  panels23.push_back(
      {mesh_panel(c.input, view, render::layers_overlay(result, {"slices"})), "(C) SLICES"});
  const std::vector<std::string> lines = {case_line(c), "method: slice_loft (no_user), layers"};
  auto files = write_figure(
      figure_sheet(panels23, 3),
      figure_caption("Slice paper, figure 23: a cone with its apex missing",
                     {"(a) the input; (b) its top view; (c) the slices around the apex (slice_"
                      "loft's layer 'slices')",
                      lines[0], lines[1]},
                     options.provenance),
      options.out_dir / "figure23_slice_cone_apex");
  view.regions_coloured = false;
  std::vector<FigurePanel> panels24 = {
      {mesh_panel(c.input, view,
                  render::layers_overlay(result, {"section_curves", "lofted_surface"})),
       "(A) RECOVERED APEX"},
      {mesh_panel(result.repaired, view), "(B) FINAL OUTPUT"}};
  for (auto& f :
       write_figure(figure_sheet(panels24, 2),
                    figure_caption("Slice paper, figure 24: the apex recovered",
                                   {"(a) the section curves traced across the hole and the "
                                    "lofted surface; (b) the final output, the patch in red",
                                    lines[0], lines[1]},
                                   options.provenance),
                    options.out_dir / "figure24_slice_cone_apex"))
    files.push_back(std::move(f));
  return files;
}

}  // namespace

std::vector<std::filesystem::path> write_slice_paper_figures(const PaperFigureOptions& options) {
  std::vector<std::filesystem::path> files;
  if (wanted(options, "figure2"))
    append(files, figure_2(options));
  for (const auto& model : slice_table_2_models()) {
    const std::string stem = "figure" + model.figure.substr(model.figure.find(' ') + 1);
    if (wanted(options, stem))
      append(files, model_figure(options, model));
  }
  if (wanted(options, "figure22"))
    append(files, figure_22(options));
  if (wanted(options, "figure23") || wanted(options, "figure24"))
    append(files, figures_23_24(options));
  return files;
}

namespace {

const JobRecord* find_record(const ResultsData& data, const std::string& case_id,
                             const std::string& method) {
  for (const auto& r : data.records) {
    if (r.job.case_id == case_id && r.job.method_id == method && r.job.noise_percent == 0.0 &&
        r.job.user == "no_user")
      return &r;
  }
  return nullptr;
}

std::string value_or_status(const JobRecord* r, const char* metric, double scale,
                            const char* format) {
  if (!r)
    return "-";
  if (const double* v = r->metric(metric))
    return fmt::format(fmt::runtime(format), *v * scale);
  return fmt::format("- ({})", to_string(r->status));
}

}  // namespace

std::vector<std::filesystem::path> write_slice_table_2_paper_rows(
    const ResultsData& data, const std::filesystem::path& out_dir) {
  const std::vector<std::string> baselines = {"liepa_cgal", "cgal_triangulate", "occt_fill",
                                              "meshlab_close_holes"};
  std::string md =
      "| paper | model (holebench case) | input tri. paper / ours | new tri. paper / ours "
      "(slice_loft) | slice_loft error x1e-3 paper / ours | slice_direct error x1e-3 paper / "
      "ours | slice_loft / slice_direct error rel. diag. |";
  for (const auto& b : baselines)
    md += " " + b + " rel. diag. |";
  md += "\n|---|---|---:|---:|---:|---:|---:|";
  for (std::size_t i = 0; i < baselines.size(); ++i)
    md += "---:|";
  md += "\n";
  std::string tex = fmt::format(
      "\\begin{{tabular}}{{llrrrrr{}}}\n\\toprule\npaper & case & input tri. & new tri. & "
      "loft $\\times 10^{{-3}}$ & direct $\\times 10^{{-3}}$ & loft / direct rel.",
      std::string(baselines.size(), 'r'));
  for (const auto& b : baselines)
    tex += " & " + latex_escape(b);
  tex += " \\\\\n\\midrule\n";
  for (const auto& model : slice_table_2_models()) {
    double diagonal = 0.0;
    try {
      diagonal = bounding_box_diagonal(generators::make_case(model.case_id).complete);
    } catch (const std::exception&) {
      // A model this machine cannot make (no CGAL data): its absolute errors are "-".
    }
    const JobRecord* loft = find_record(data, model.case_id, "slice_loft");
    const JobRecord* direct = find_record(data, model.case_id, "slice_direct");
    const auto absolute = [&](const JobRecord* r) {
      return diagonal > 0.0 ? value_or_status(r, metric_names::kNewVertexMeanErrorRelDiag,
                                              diagonal * 1e3, "{:.3f}")
                            : std::string("-");
    };
    const std::vector<std::string> cells = {
        fmt::format("{} / {}", model.paper_input_triangles,
                    value_or_status(loft, metric_names::kInputFacesCount, 1.0, "{:.0f}")),
        fmt::format("{} / {}", model.paper_new_triangles,
                    value_or_status(loft, metric_names::kNewFacesCount, 1.0, "{:.0f}")),
        fmt::format("{:.3f} / {}", model.paper_loft_error_e3, absolute(loft)),
        fmt::format("{:.3f} / {}", model.paper_direct_error_e3, absolute(direct)),
        fmt::format(
            "{} / {}",
            value_or_status(loft, metric_names::kNewVertexMeanErrorRelDiag, 1.0, "{:.3e}"),
            value_or_status(direct, metric_names::kNewVertexMeanErrorRelDiag, 1.0, "{:.3e}"))};
    std::vector<std::string> baseline_cells;
    for (const auto& b : baselines)
      baseline_cells.push_back(value_or_status(find_record(data, model.case_id, b),
                                               metric_names::kNewVertexMeanErrorRelDiag, 1.0,
                                               "{:.3e}"));
    md += fmt::format("| {} | {} (`{}`) | {} | {} |\n", model.figure, model.what, model.case_id,
                      fmt::join(cells, " | "), fmt::join(baseline_cells, " | "));
    std::vector<std::string> tex_cells = {latex_escape(model.figure), latex_escape(model.case_id)};
    for (const auto& c : cells)
      tex_cells.push_back(latex_escape(c));
    for (const auto& c : baseline_cells)
      tex_cells.push_back(latex_escape(c));
    tex += fmt::format("{} \\\\\n", fmt::join(tex_cells, " & "));
  }
  tex += "\\bottomrule\n\\end{tabular}\n";
  md +=
      "\nThe slice paper's Table 2 with its four rows: the paper's numbers (its models, errors in "
      "its model units times 1e3) beside ours on the holebench case that stands for each model, "
      "at noise 0 and no_user. Error: the mean distance of the new vertices from the complete "
      "model (`new_vertex_mean_error_rel_diag`), in the model's units times 1e3 (the paper's "
      "unit; our models' sizes differ from the paper's, so compare the relative columns across "
      "models) and relative to the bounding-box diagonal. `-`: no record in these results (run "
      "`holebench run --suite paper`), or no new vertex (the record's status in brackets).\n";
  const auto md_path = out_dir / "table2_slice_paper_rows.md";
  const auto tex_path = out_dir / "table2_slice_paper_rows.tex";
  std::ofstream(md_path) << md;
  std::ofstream(tex_path) << tex;
  return {md_path, tex_path};
}

}  // namespace holebench::harness
