#include "harness/figures/paper_figures.h"

#include "generators/case_catalog.h"
#include "harness/figures/crest_paper_figures.h"
#include "harness/figures/slice_ablation_table.h"
#include "harness/figures/slice_paper_figures.h"
#include "harness/outputs/render/case_view.h"
#include "harness/outputs/report/summary_table.h"
#include "harness/results/markup_escape.h"
#include "harness/results/run_context.h"
#include "methods/registry.h"
#include "metrics/metric_names.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

namespace holebench::harness {
namespace {

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
      render::paste(sheet, render::job_snapshot(c, result, snapshot),
                    static_cast<int>(column) * options.tile_width, row * options.tile_height);
    }
  }
  const auto path = options.out_dir / "figure5_brep_k3_inner.png";
  render::write_png(sheet, path);
  return path;
}

// The methods Table 2 of the slice paper compares (its columns).
const std::vector<std::string> kTable2Methods = {"slice_loft", "slice_direct", "liepa_cgal"};

std::string cell(const std::vector<double>& values, const char* format = "{:.3e}") {
  if (values.empty())
    return "-";
  double sum = 0.0;
  for (double v : values)
    sum += v;
  return fmt::format(fmt::runtime(format), sum / values.size());
}

// The kind of hole a CAD case's target makes, as Table 2's breakdown names it.
std::string target_kind(const std::string& target) {
  if (target == "face_interior")
    return "face";
  if (target.rfind("edge_", 0) == 0)
    return "edge";
  if (target.rfind("corner_", 0) == 0 || target == "cone_apex")
    return "corner";
  if (target == "curved_face")
    return "curved";
  return target;  // island, multi_feature
}

// One row of Table 2: the means over the small holes on which every compared method left new
// vertices (paired), so each column averages the same holes.
struct Table2Row {
  std::vector<double> input_triangles, new_triangles;
  std::map<std::string, std::vector<double>> error;
};

// Table 2's rows keyed by `row_key(case id)` and noise level, from the records of the small
// holes of the CAD models.
template <typename RowKey>
std::map<std::pair<std::string, double>, Table2Row> table_2_rows(const ResultsData& data,
                                                                 RowKey row_key) {
  const auto& methods = kTable2Methods;
  struct HoleRecords {  // one hole's records, per method
    std::map<std::string, const JobRecord*> by_method;
  };
  std::map<std::tuple<std::string, double, std::uint64_t, std::string>, HoleRecords> jobs;
  for (const auto& r : data.records) {
    const std::string& id = r.job.case_id;
    if (r.case_family != "cad" || r.job.user != "no_user" || id.size() < 6 ||
        id.compare(id.size() - 6, 6, "/small") != 0)
      continue;
    if (std::find(methods.begin(), methods.end(), r.job.method_id) == methods.end())
      continue;
    jobs[{id, r.job.noise_percent, r.job.seed, r.job.user}].by_method[r.job.method_id] = &r;
  }
  std::map<std::pair<std::string, double>, Table2Row> rows;
  for (const auto& [key, job] : jobs) {
    std::map<std::string, double> error;
    for (const auto& method : methods) {
      const auto it = job.by_method.find(method);
      if (it == job.by_method.end())
        continue;
      if (const double* value = it->second->metric(metric_names::kNewVertexMeanErrorRelDiag))
        error[method] = *value;
    }
    if (error.size() != methods.size())
      continue;  // not every method left new vertices: the hole is in no column
    Table2Row& row = rows[{row_key(std::get<0>(key)), std::get<1>(key)}];
    for (const auto& [method, value] : error)
      row.error[method].push_back(value);
    const JobRecord& loft = *job.by_method.at("slice_loft");
    if (const double* faces = loft.metric(metric_names::kNewFacesCount))
      row.new_triangles.push_back(*faces);
    if (const double* input = loft.metric(metric_names::kInputFacesCount))
      row.input_triangles.push_back(*input);
  }
  return rows;
}

// Writes one Table 2 (markdown and LaTeX) whose first column is `what`.
std::vector<std::filesystem::path> write_table_2(
    const std::map<std::pair<std::string, double>, Table2Row>& rows, const std::string& what,
    const std::filesystem::path& stem) {
  const auto& methods = kTable2Methods;
  std::string md =
      fmt::format("| {} | noise % | holes | input triangles | new triangles (slice_loft) | {} |\n",
                  what, fmt::join(methods, " | "));
  md += "|---|---:|---:|---:|---:|";
  for (std::size_t i = 0; i < methods.size(); ++i)
    md += "---:|";
  md += "\n";
  std::string tex = fmt::format(
      "\\begin{{tabular}}{{lrrrr{}}}\n\\toprule\n{} & noise \\% & holes & "
      "input tri. & new tri.",
      std::string(methods.size(), 'r'), what);
  for (const auto& method : methods)
    tex += " & " + latex_escape(method);
  tex += " \\\\\n\\midrule\n";
  for (const auto& [key, row] : rows) {
    std::vector<std::string> values = {fmt::format("{}", row.error.begin()->second.size()),
                                       cell(row.input_triangles, "{:.0f}"),
                                       cell(row.new_triangles, "{:.0f}")};
    for (const auto& method : methods)
      values.push_back(
          cell(row.error.count(method) ? row.error.at(method) : std::vector<double>{}));
    md += fmt::format("| {} | {} | {} |\n", key.first, key.second, fmt::join(values, " | "));
    tex += fmt::format("{} & {} & {} \\\\\n", latex_escape(key.first), key.second,
                       fmt::join(values, " & "));
  }
  tex += "\\bottomrule\n\\end{tabular}\n";
  if (rows.empty())
    md +=
        "| (no CAD records of every method in these results: run `holebench run --suite paper`) "
        "|\n";
  const std::string note =
      "\nMean new-vertex error (mean distance of the new vertices from the complete model, "
      "relative to its bounding-box diagonal) over the small holes on which every method in the "
      "table left new vertices (`holes` of them: the columns average the same holes), as in "
      "Table 2 of the slice paper.\n";
  auto md_path = stem;
  md_path += ".md";
  auto tex_path = stem;
  tex_path += ".tex";
  std::ofstream(md_path) << md << note;
  std::ofstream(tex_path) << tex;
  return {md_path, tex_path};
}

// Table 2: per CAD model and noise level; and the same per kind of target (face, edge,
// corner, curved, island, multi_feature).
std::vector<std::filesystem::path> table_2(const ResultsData& data, const FiguresOptions& options) {
  auto model = [](const std::string& id) { return id.substr(4, id.find('/', 4) - 4); };
  auto kind = [](const std::string& id) {
    const std::size_t from = id.find('/', 4) + 1;
    return target_kind(id.substr(from, id.find('/', from) - from));
  };
  auto files = write_table_2(table_2_rows(data, model), "model",
                             options.out_dir / "table2_slice_new_vertex_error");
  for (auto& f : write_table_2(table_2_rows(data, kind), "target kind",
                               options.out_dir / "table2_by_target_kind"))
    files.push_back(std::move(f));
  return files;
}

// Figures 10 and 13 of the crest-line paper: holes across 1, 2, 3 creases of the fandisk.
std::vector<std::filesystem::path> crease_table(const ResultsData& data,
                                                const FiguresOptions& options) {
  const std::vector<std::string> columns = {
      metric_names::kHausdorffRelDiag, metric_names::kHoleMeanDistanceRelDiag,
      metric_names::kNewVertexMeanErrorRelDiag, metric_names::kMissingEdgePresentFraction};
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
      const double* v = r->metric(c);
      md += v ? fmt::format(" {:.3e} |", *v) : std::string(" - |");
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

const std::vector<std::string>& paper_figure_names() {
  static const std::vector<std::string> names = {"figure5",  "figure2",  "figure17", "figure18",
                                                 "figure19", "figure20", "figure22", "figure23",
                                                 "figure10", "figure12", "figure13"};
  return names;
}

std::vector<std::filesystem::path> write_paper_figures(const FiguresOptions& options) {
  for (const auto& name : options.only) {
    const auto& names = paper_figure_names();
    if (name != "figure24" && std::find(names.begin(), names.end(), name) == names.end())
      throw std::invalid_argument(
          fmt::format("unknown figure '{}' (known: {}, figure24)", name, fmt::join(names, ", ")));
  }
  std::filesystem::create_directories(options.out_dir);
  std::optional<ResultsData> data;
  FigureProvenance provenance;
  provenance.code_version = current_context("").code_version;
  if (options.results) {
    data = read_results_json(*options.results);
    provenance.run = fmt::format("{} (suite {}, code {})", options.results->generic_string(),
                                 data->context.suite, data->context.code_version);
  }
  PaperFigureOptions rendered;
  rendered.out_dir = options.out_dir;
  rendered.panel_size = options.panel_size;
  rendered.samples_per_axis = options.samples_per_axis;
  rendered.provenance = provenance;
  rendered.only = options.only;  // figure24 asks for figure 23 too: they are rendered together
  std::vector<std::filesystem::path> written;
  if (wanted(rendered, "figure5"))
    written.push_back(figure_5(options));
  append(written, write_slice_paper_figures(rendered));
  append(written, write_crest_paper_figures(rendered));
  if (data) {
    append(written, table_2(*data, options));
    append(written, write_slice_table_2_paper_rows(*data, options.out_dir));
    append(written, write_slice_ablation_table(*data, options.out_dir));
    append(written, crease_table(*data, options));
  }
  return written;
}

}  // namespace holebench::harness
