#include "harness/outputs/paper_figures.h"

#include "generators/case_catalog.h"
#include "harness/outputs/render/case_view.h"
#include "harness/outputs/report/summary_table.h"
#include "methods/registry.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>

namespace holebench::harness {
namespace {

// Copies `tile` into `sheet` at (x0, y0).
void paste(render::Image& sheet, const render::Image& tile, int x0, int y0) {
  for (int y = 0; y < tile.height; ++y) {
    for (int x = 0; x < tile.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        sheet.pixels[(static_cast<std::size_t>(y0 + y) * sheet.width + x0 + x) * 3 + c] =
            tile.pixels[(static_cast<std::size_t>(y) * tile.width + x) * 3 + c];
      }
    }
  }
}

std::filesystem::path figure_5(const FiguresOptions& options) {
  const std::vector<std::string> patterns = {"convex-convex-convex", "convex-convex-reflex",
                                             "convex-reflex-reflex", "reflex-reflex-reflex"};
  const auto method = make_method("brep_guidance");
  render::Image sheet(options.tile_width * 4, options.tile_height * 2);
  render::SnapshotOptions snapshot;
  snapshot.width = options.tile_width;
  snapshot.height = options.tile_height;
  for (std::size_t column = 0; column < patterns.size(); ++column) {
    for (int row = 0; row < 2; ++row) {
      // Above: the large hole, guided; below: the small one, closed automatically.
      const std::string id =
          fmt::format("brep/k3/inner/{}/{}", patterns[column], row == 0 ? "large" : "small");
      const Case c = generators::make_case(id);
      NoUser user;
      MethodParameters parameters;
      parameters.structure_size = c.parameters.structure_size;
      const MethodResult result = method->run(c.input, parameters, user);
      paste(sheet, render::job_snapshot(c, result, snapshot),
            static_cast<int>(column) * options.tile_width, row * options.tile_height);
    }
  }
  const auto path = options.out_dir / "figure5_brep_k3_inner.png";
  render::write_png(sheet, path);
  return path;
}

// The methods Table 2 of the slice paper compares (its columns).
const std::vector<std::string> kTable2Methods = {"slice_loft", "slice_direct", "liepa_cgal"};

double metric(const JobRecord& record, const std::string& name, bool& found) {
  for (const auto& m : record.metrics) {
    if (m.name == name) {
      found = true;
      return m.value;
    }
  }
  found = false;
  return 0.0;
}

std::string cell(const std::vector<double>& values, const char* format = "{:.3e}") {
  if (values.empty())
    return "-";
  double sum = 0.0;
  for (double v : values)
    sum += v;
  return fmt::format(fmt::runtime(format), sum / values.size());
}

// Table 2: per CAD model and noise level, the mean over the model's small holes.
std::vector<std::filesystem::path> table_2(const ResultsData& data, const FiguresOptions& options) {
  const auto& methods = kTable2Methods;
  struct Row {
    std::vector<double> input_triangles, new_triangles;
    std::map<std::string, std::vector<double>> error;
  };
  std::map<std::pair<std::string, double>, Row> rows;
  for (const auto& r : data.records) {
    if (r.case_family != "cad" || r.job.user != "no_user")
      continue;
    const std::string model = r.job.case_id.substr(4, r.job.case_id.find('/', 4) - 4);
    Row& row = rows[{model, r.job.noise_percent}];
    bool found = false;
    const double error = metric(r, "new_vertex_mean_error_rel_diag", found);
    if (found && std::find(methods.begin(), methods.end(), r.job.method_id) != methods.end()) {
      row.error[r.job.method_id].push_back(error);
    }
    if (r.job.method_id == "slice_loft") {
      const double faces = metric(r, "new_faces_count", found);
      if (found)
        row.new_triangles.push_back(faces);
      const double input = metric(r, "input_faces_count", found);
      if (found)
        row.input_triangles.push_back(input);
    }
  }
  std::string md =
      "| model | noise % | input triangles | new triangles (slice_loft) | slice_loft | "
      "slice_direct | liepa_cgal |\n"
      "|---|---:|---:|---:|---:|---:|---:|\n";
  std::string tex =
      "\\begin{tabular}{lrrrrrr}\n\\toprule\nmodel & noise \\% & input tri. & new tri. & "
      "slice\\_loft & "
      "slice\\_direct & liepa\\_cgal \\\\\n\\midrule\n";
  for (const auto& [key, row] : rows) {
    const std::vector<std::string> values = {
        cell(row.input_triangles, "{:.0f}"), cell(row.new_triangles, "{:.0f}"),
        cell(row.error.count("slice_loft") ? row.error.at("slice_loft") : std::vector<double>{}),
        cell(row.error.count("slice_direct") ? row.error.at("slice_direct")
                                             : std::vector<double>{}),
        cell(row.error.count("liepa_cgal") ? row.error.at("liepa_cgal") : std::vector<double>{})};
    md += fmt::format("| {} | {} | {} |\n", key.first, key.second, fmt::join(values, " | "));
    tex += fmt::format("{} & {} & {} \\\\\n", report::latex_escape(key.first), key.second,
                       fmt::join(values, " & "));
  }
  tex += "\\bottomrule\n\\end{tabular}\n";
  if (rows.empty())
    md += "| (no CAD records in these results: run `holebench run --suite paper`) |||||||\n";
  const std::string note =
      "\nMean new-vertex error (mean distance of the new vertices from the complete model, "
      "relative to its "
      "bounding-box diagonal) over each model's small holes, as in Table 2 of the slice paper.\n";
  const auto md_path = options.out_dir / "table2_slice_new_vertex_error.md";
  const auto tex_path = options.out_dir / "table2_slice_new_vertex_error.tex";
  std::ofstream(md_path) << md << note;
  std::ofstream(tex_path) << tex;
  return {md_path, tex_path};
}

// Figures 10 and 13 of the crest-line paper: holes across 1, 2, 3 creases of the fandisk.
std::vector<std::filesystem::path> crease_table(const ResultsData& data,
                                                const FiguresOptions& options) {
  const std::vector<std::string> columns = {"hausdorff_rel_diag", "hole_mean_distance_rel_diag",
                                            "new_vertex_mean_error_rel_diag",
                                            "missing_edge_present_fraction"};
  std::string md = "| case | method | user | noise % | status |";
  for (const auto& c : columns)
    md += " " + c + " |";
  md += "\n|---|---|---|---:|---|";
  for (std::size_t i = 0; i < columns.size(); ++i)
    md += "---:|";
  md += "\n";
  std::vector<const JobRecord*> records;
  for (const auto& r : data.records) {
    if (r.case_family == "crease")
      records.push_back(&r);
  }
  std::sort(records.begin(), records.end(),
            [](const JobRecord* a, const JobRecord* b) { return a->job.id() < b->job.id(); });
  if (records.empty())
    md += "| (no crease records in these results: run `holebench run --suite paper`) |\n";
  for (const JobRecord* r : records) {
    md += fmt::format("| {} | {} | {} | {} | {} |", r->job.case_id, r->job.method_id, r->job.user,
                      r->job.noise_percent, to_string(r->status));
    for (const auto& c : columns) {
      bool found = false;
      const double v = metric(*r, c, found);
      md += found ? fmt::format(" {:.3e} |", v) : std::string(" - |");
    }
    md += "\n";
  }
  const auto path = options.out_dir / "figures10_13_crest_creases.md";
  std::ofstream(path) << md;
  return {path};
}

}  // namespace

std::vector<std::string> paper_figure_gaps(const ResultsData& data) {
  std::set<std::string> cad_methods;
  bool crease = false;
  for (const auto& r : data.records) {
    if (r.case_family == "cad")
      cad_methods.insert(r.job.method_id);
    crease = crease || r.case_family == "crease";
  }
  std::vector<std::string> gaps;
  if (cad_methods.empty()) {
    gaps.push_back("no CAD records: Table 2 of the slice paper is empty");
  } else {
    for (const auto& method : kTable2Methods) {
      if (!cad_methods.count(method))
        gaps.push_back(fmt::format("no CAD records of {}: its Table 2 column is empty", method));
    }
  }
  if (!crease)
    gaps.push_back("no crease records: the crest-line paper's figures 10/13 table is empty");
  return gaps;
}

std::vector<std::filesystem::path> write_paper_figures(const FiguresOptions& options) {
  std::filesystem::create_directories(options.out_dir);
  std::vector<std::filesystem::path> written{figure_5(options)};
  if (options.results) {
    const ResultsData data = read_results_json(*options.results);
    for (const auto& p : table_2(data, options))
      written.push_back(p);
    for (const auto& p : crease_table(data, options))
      written.push_back(p);
  }
  return written;
}

}  // namespace holebench::harness
