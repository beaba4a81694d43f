#include "harness/outputs/viewer/viewer_page.h"

#include "core/environment_path.h"
#include "harness/outputs/file_bytes.h"
#include "harness/outputs/render/close_up.h"
#include "harness/outputs/render/heat_map.h"
#include "harness/outputs/viewer/viewer_mesh.h"
#include "harness/outputs/viewer/viewer_script.h"
#include "harness/results/markup_escape.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <map>
#include <stdexcept>
#include <tuple>

namespace holebench::viewer {
namespace {

using harness::base64;
using harness::read_bytes;

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out)
    throw std::runtime_error(path.string() + ": cannot write");
}

/// One case of the viewer: its meshes by the name the tick boxes show.
struct ViewerCase {
  std::string label;
  std::vector<std::pair<std::string, std::filesystem::path>> meshes;
};

/// The cases whose complete and holed meshes exist, each with the repaired meshes of its
/// jobs (named by method, and user where it is not no_user), in the records' order.
std::vector<ViewerCase> find_cases(const harness::ResultsData& data,
                                   const std::filesystem::path& results_dir) {
  using Key = std::tuple<std::string, double, std::uint64_t>;
  std::map<Key, ViewerCase> by_key;
  std::vector<Key> order;
  for (const auto& record : data.records) {
    const auto& job = record.job;
    const auto repaired = results_dir / repaired_mesh_file(job);
    if (!std::filesystem::exists(repaired))
      continue;
    const Key key{job.case_id, job.noise_percent, job.seed};
    auto [it, inserted] = by_key.try_emplace(key);
    ViewerCase& c = it->second;
    if (inserted) {
      const auto complete = results_dir / complete_mesh_file(job);
      const auto holed = results_dir / holed_mesh_file(job);
      if (!std::filesystem::exists(complete) || !std::filesystem::exists(holed)) {
        by_key.erase(it);
        continue;
      }
      order.push_back(key);
      c.label = fmt::format("{} (noise {} %, seed {})", job.case_id, job.noise_percent, job.seed);
      c.meshes.emplace_back("complete", complete);
      c.meshes.emplace_back("holed", holed);
    }
    const std::string name =
        job.user == "no_user" ? job.method_id : job.method_id + " (" + job.user + ")";
    c.meshes.emplace_back(name, repaired);
  }
  std::sort(order.begin(), order.end());
  std::vector<ViewerCase> out;
  for (const auto& key : order)
    out.push_back(std::move(by_key.at(key)));
  return out;
}

nlohmann::json colour_json(const render::Rgb& c) {
  return nlohmann::json::array({c.r, c.g, c.b});
}

std::string config_json() {
  nlohmann::json config;
  config["stops"] = nlohmann::json::array();
  for (const auto& stop : render::heat_stops())
    config["stops"].push_back(colour_json(stop));
  config["kept"] = colour_json(render::kept_colour());
  config["open"] = colour_json(render::open_hole_colour());
  config["background"] = "#1d2433";
  return config.dump();
}

/// JSON inside a <script> element: "</" may not appear.
std::string script_safe(std::string json) {
  std::string out;
  for (std::size_t i = 0; i < json.size(); ++i) {
    if (json[i] == '<' && i + 1 < json.size() && json[i + 1] == '/')
      out += "<\\";
    else
      out += json[i];
  }
  return out;
}

std::string section_html(const std::string& body) {
  return "<h2 id=\"viewer\">3D viewer</h2>\n" + body;
}

}  // namespace

std::filesystem::path three_dir(const ViewerOptions& options) {
  if (!options.three_dir.empty())
    return options.three_dir;
  return environment_path_or("HOLEBENCH_THREE_DIR", "/usr/share/javascript/three");
}

ViewerSection write_viewer(const harness::ResultsData& data,
                           const std::filesystem::path& results_dir,
                           const std::filesystem::path& report_dir, const ViewerOptions& options) {
  ViewerSection section;
  std::vector<ViewerCase> cases = find_cases(data, results_dir);
  const auto three = three_dir(options);
  const auto three_js = three / "three.min.js";
  const auto orbit_js = three / "examples" / "js" / "controls" / "OrbitControls.js";
  if (cases.empty()) {
    section.note = "no case has viewer meshes (holebench run writes them with the snapshots)";
  } else if (!std::filesystem::exists(three_js) || !std::filesystem::exists(orbit_js)) {
    section.note =
        fmt::format("three.js is missing ({} and {}; Debian: apt-get install libjs-three)",
                    three_js.string(), orbit_js.string());
  }
  if (!section.note.empty()) {
    section.html = section_html(
        "<p class=\"none\">No 3D viewer: " + harness::xml_escape(section.note) + ".</p>\n");
    return section;
  }
  std::string left_out;
  if (cases.size() > options.max_cases) {
    left_out = fmt::format(" The first {} of {} cases are here.", options.max_cases, cases.size());
    cases.resize(options.max_cases);
  }
  const auto dir = report_dir / "viewer";
  std::filesystem::create_directories(dir / "data");
  std::filesystem::copy_file(three_js, dir / "three.min.js",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(orbit_js, dir / "OrbitControls.js",
                             std::filesystem::copy_options::overwrite_existing);
  write_text(dir / "viewer.js", viewer_script());
  section.files = {"viewer/OrbitControls.js", "viewer/three.min.js", "viewer/viewer.js"};

  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    nlohmann::json payload = nlohmann::json::object();
    nlohmann::json names = nlohmann::json::array();
    for (const auto& [name, path] : cases[i].meshes) {
      payload[name] = base64(read_bytes(path));
      names.push_back(name);
    }
    const std::string file = fmt::format("viewer/data/{}.js", i);
    write_text(report_dir / file,
               fmt::format("holebenchViewer.receive({}, {});\n", i, payload.dump()));
    section.files.push_back(file);
    list.push_back({{"id", cases[i].label}, {"data", file}, {"meshes", names}});
  }
  section.cases = cases.size();
  section.html = section_html(fmt::format(
      "<p>Per case, the complete model, the holed input and each method's repaired mesh, as the "
      "run wrote them (<code>meshes/*.ply</code>). It opens on the case's first hole, "
      "seen as the close-up snapshot sees it; <em>whole model</em> shows the models whole. Drag "
      "to turn, scroll to zoom, right-drag to pan; tick the meshes to show them side by side at "
      "the same scale (one ticked: one at a time). Kept faces are grey; the patch is "
      "coloured by its distance to the complete model relative to the diagonal, on the case's "
      "scale (the bar; the same as in the snapshots); open holes are outlined in magenta.{}</p>\n"
      "<div class=\"viewer-controls\"><select id=\"viewer-case\"></select> <button "
      "id=\"viewer-whole\" type=\"button\">whole model</button> <span "
      "id=\"viewer-toggles\"></span></div>\n"
      "<div class=\"viewer-box\"><canvas id=\"viewer-canvas\"></canvas><div "
      "id=\"viewer-bar\"></div></div>\n<p id=\"viewer-status\">The viewer needs JavaScript and "
      "WebGL.</p>\n"
      "<script type=\"application/json\" id=\"viewer-config\">{}</script>\n"
      "<script type=\"application/json\" id=\"viewer-cases\">{}</script>\n"
      "<script src=\"viewer/three.min.js\"></script>\n<script "
      "src=\"viewer/OrbitControls.js\"></script>\n<script src=\"viewer/viewer.js\"></script>\n",
      left_out, script_safe(config_json()), script_safe(list.dump())));
  return section;
}

}  // namespace holebench::viewer
