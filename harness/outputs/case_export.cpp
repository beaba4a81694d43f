#include "harness/outputs/case_export.h"

#include "core/geometry.h"
#include "core/mesh_io.h"
#include "harness/results/record_json.h"

#include <nlohmann/json.hpp>

#include <fstream>
#include <stdexcept>

namespace holebench::harness {

nlohmann::ordered_json case_to_json(const Case& c) {
  nlohmann::ordered_json j;
  j["id"] = c.id;
  j["family"] = c.family;
  j["kind"] = c.kind;
  j["seed"] = c.seed;
  j["noise_percent"] = c.noise_percent;
  j["complete_bounding_box_diagonal"] = bounding_box_diagonal(c.complete);
  if (!c.has_ground_truth)
    j["has_ground_truth"] = false;  // a real hole: "complete" is the open mesh itself
  auto& holes = j["holes"] = nlohmann::ordered_json::array();
  for (const auto& hole : c.holes) {
    nlohmann::ordered_json h;
    h["target"] = hole.target;
    h["removed_faces"] = hole.removed_faces;
    auto& edges = h["missing_edges"] = nlohmann::ordered_json::array();
    for (const auto& polyline : hole.missing_edges) {
      nlohmann::ordered_json line = nlohmann::ordered_json::array();
      for (const Point& p : polyline)
        line.push_back(point_to_json(p));
      edges.push_back(line);
    }
    auto& corners = h["missing_corners"] = nlohmann::ordered_json::array();
    for (const Point& p : hole.missing_corners)
      corners.push_back(point_to_json(p));
    h["labels"] = hole.labels ? labels_to_json(*hole.labels) : nlohmann::ordered_json();
    holes.push_back(h);
  }
  return j;
}

void export_case(const Case& c, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  WriteOptions ply;
  write_mesh(c.input, dir / "input.ply", ply);
  write_mesh(c.input, dir / "input.off");
  write_mesh(c.complete, dir / "complete.ply", ply);
  write_mesh(c.complete, dir / "complete.off");

  nlohmann::ordered_json j = case_to_json(c);
  j["files"] = {{"input", "input.ply"}, {"complete", "complete.ply"}};
  std::ofstream out(dir / "case.json");
  out << j.dump(2) << '\n';
  if (!out)
    throw std::runtime_error("cannot write " + (dir / "case.json").string());
}

}  // namespace holebench::harness
