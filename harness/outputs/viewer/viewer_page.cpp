#include "harness/outputs/viewer/viewer_page.h"

#include "core/environment_path.h"
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

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out)
    throw std::runtime_error(path.string() + ": cannot write");
}

/// One mesh of a case: the name its tick box shows, its file, and whether it is a job's patch
/// (assembled with the case's holed mesh in the page).
struct ViewerCaseMesh {
  std::string name;
  std::filesystem::path file;
  bool patch = false;
};

/// One case of the viewer: its meshes in the order of the tick boxes.
struct ViewerCase {
  std::string label;
  std::vector<ViewerCaseMesh> meshes;
};

/// The cases whose complete and holed meshes exist, each with the patches of its jobs (named
/// by method, and user where it is not no_user), in the records' order.
std::vector<ViewerCase> find_cases(const harness::ResultsData& data,
                                   const std::filesystem::path& results_dir) {
  using Key = std::tuple<std::string, double, std::uint64_t>;
  std::map<Key, ViewerCase> by_key;
  std::vector<Key> order;
  for (const auto& record : data.records) {
    const auto& job = record.job;
    const auto patch = results_dir / patch_mesh_file(job);
    if (!std::filesystem::exists(patch))
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
      c.meshes.push_back({"complete", complete, false});
      c.meshes.push_back({"holed", holed, false});
    }
    const std::string name =
        job.user == "no_user" ? job.method_id : job.method_id + " (" + job.user + ")";
    c.meshes.push_back({name, patch, true});
  }
  std::sort(order.begin(), order.end());
  std::vector<ViewerCase> out;
  for (const auto& key : order)
    out.push_back(std::move(by_key.at(key)));
  return out;
}

/// `file` as the report page links it: relative to the report folder, '/'-separated.
std::string link_from(const std::filesystem::path& report_dir, const std::filesystem::path& file) {
  const auto absolute_report =
      std::filesystem::weakly_canonical(std::filesystem::absolute(report_dir));
  const auto absolute_file = std::filesystem::weakly_canonical(std::filesystem::absolute(file));
  return absolute_file.lexically_relative(absolute_report).generic_string();
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
  std::filesystem::create_directories(dir);
  std::filesystem::remove_all(dir / "data");  // an older report's copies of the meshes
  std::filesystem::copy_file(three_js, dir / "three.min.js",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(orbit_js, dir / "OrbitControls.js",
                             std::filesystem::copy_options::overwrite_existing);
  write_text(dir / "viewer.js", viewer_script());
  section.files = {"viewer/OrbitControls.js", "viewer/three.min.js", "viewer/viewer.js"};

  nlohmann::json list = nlohmann::json::array();
  // The meshes stay where the run wrote them: the page loads each file by its link.
  for (const auto& c : cases) {
    nlohmann::json names = nlohmann::json::array();
    nlohmann::json files = nlohmann::json::array();
    nlohmann::json patches = nlohmann::json::array();
    for (const auto& mesh : c.meshes) {
      names.push_back(mesh.name);
      files.push_back(link_from(report_dir, mesh.file));
      patches.push_back(mesh.patch);
    }
    list.push_back({{"id", c.label}, {"meshes", names}, {"files", files}, {"patch", patches}});
  }
  section.cases = cases.size();
  section.html = section_html(fmt::format(
      "<p>Per case, the complete model, the holed input and each method's repaired mesh (the "
      "holed input and the method's patch), loaded from the files the run wrote "
      "(<code>meshes/*.js</code>). It opens on the case's first hole, "
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
