#include "harness/outputs/viewer/viewer_mesh.h"

#include "generators/case_catalog.h"
#include "methods/registry.h"
#include "methods/user.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace holebench::viewer {
namespace {

std::string read_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct PlyCounts {
  std::size_t vertices = 0, faces = 0, edges = 0, body = 0;
  double scale = 0.0;
};

/// The header's element counts and the size of the binary body.
PlyCounts read_counts(const std::string& bytes) {
  const std::size_t end = bytes.find("end_header\n");
  std::istringstream header(bytes.substr(0, end));
  PlyCounts counts;
  std::string line;
  while (std::getline(header, line)) {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == "element" && second == "vertex")
      words >> counts.vertices;
    if (first == "element" && second == "face")
      words >> counts.faces;
    if (first == "element" && second == "edge")
      words >> counts.edges;
    if (first == "comment" && second == "heat_scale_max_rel_diag")
      words >> counts.scale;
  }
  counts.body = bytes.size() - end - std::strlen("end_header\n");
  return counts;
}

// The holed box corner: every face written once, no patch, its one hole's loop as open
// edges; the body is 16 bytes per vertex, 14 per face, 8 per edge.
TEST(ViewerMesh, PlainMeshHasItsFacesAndOpenEdges) {
  const Case c = generators::make_case("box/corner");
  const auto path = std::filesystem::temp_directory_path() / "viewer_mesh_plain.ply";
  write_plain_mesh(c.input, path);
  const PlyCounts counts = read_counts(read_bytes(path));
  EXPECT_EQ(counts.vertices, c.input.n_vertices());
  EXPECT_EQ(counts.faces, c.input.n_faces());
  EXPECT_GT(counts.edges, 2u);
  EXPECT_EQ(counts.body, 16 * counts.vertices + 14 * counts.faces + 8 * counts.edges);
  EXPECT_EQ(counts.scale, 0.0);
}

// A repaired box corner: no open edge, the case's heat scale in the header, and the patch
// split into pieces (more faces than the repaired mesh has).
TEST(ViewerMesh, RepairedMeshSplitsThePatchAndNamesTheScale) {
  const Case c = generators::make_case("box/corner");
  NoUser user;
  const MethodResult result = make_method("liepa_cgal")->run(c.input, {}, user);
  const auto path = std::filesystem::temp_directory_path() / "viewer_mesh_repaired.ply";
  write_repaired_mesh(c, result.repaired, path);
  const PlyCounts counts = read_counts(read_bytes(path));
  EXPECT_EQ(counts.edges, 0u);
  EXPECT_GT(counts.faces, result.repaired.n_faces());
  EXPECT_GT(counts.scale, 0.0);
  EXPECT_EQ(counts.body, 16 * counts.vertices + 14 * counts.faces + 8 * counts.edges);
}

// File names: one case variant per case id, noise and seed; one repaired mesh per job.
TEST(ViewerMesh, FileNamesFollowTheJob) {
  harness::Job job;
  job.case_id = "cad/fandisk/edge/small";
  job.method_id = "liepa_cgal";
  job.noise_percent = 5;
  job.seed = 1;
  EXPECT_EQ(complete_mesh_file(job), "meshes/cad_fandisk_edge_small_5_1.complete.ply");
  EXPECT_EQ(holed_mesh_file(job), "meshes/cad_fandisk_edge_small_5_1.holed.ply");
  EXPECT_EQ(repaired_mesh_file(job),
            "meshes/cad_fandisk_edge_small_liepa_cgal_no_user_5_1.repaired.ply");
}

}  // namespace
}  // namespace holebench::viewer
