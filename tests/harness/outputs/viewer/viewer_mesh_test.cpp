#include "harness/outputs/viewer/viewer_mesh.h"

#include "core/boundary_loops.h"
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

struct PlyCounts {
  std::size_t vertices = 0, faces = 0, edges = 0, sewn = 0, dropped = 0, body = 0;
  bool split = false;  ///< faces carry splits and split_quality
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
    if (first == "element" && second == "sewn_vertex")
      words >> counts.sewn;
    if (first == "element" && second == "dropped_face")
      words >> counts.dropped;
    if (first == "property" && line.find(" splits") != std::string::npos)
      counts.split = true;
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
  const auto path = std::filesystem::temp_directory_path() / "viewer_mesh_plain.js";
  write_plain_mesh(c.input, path);
  const PlyCounts counts = read_counts(read_viewer_ply(path));
  EXPECT_EQ(counts.vertices, c.input.n_vertices());
  EXPECT_EQ(counts.faces, c.input.n_faces());
  EXPECT_GT(counts.edges, 2u);
  EXPECT_EQ(counts.body, 16 * counts.vertices + 14 * counts.faces + 8 * counts.edges);
  EXPECT_EQ(counts.scale, 0.0);
}

// A repaired box corner's patch: no open edge, the case's heat scale in the header, its new
// faces alone with the distances of their splits, every input face kept, and the patch sewn
// to the hole's boundary: each boundary vertex of the holed mesh is named.
TEST(ViewerMesh, PatchSplitsTheNewFacesAndNamesWhereItIsSewn) {
  const Case c = generators::make_case("box/corner");
  NoUser user;
  const MethodResult result = make_method("liepa_cgal")->run(c.input, {}, user);
  const auto path = std::filesystem::temp_directory_path() / "viewer_mesh_patch.js";
  write_patch_mesh(c, result.repaired, path);
  const PlyCounts counts = read_counts(read_viewer_ply(path));
  const std::size_t new_faces = result.repaired.n_faces() - c.input.n_faces();
  EXPECT_EQ(counts.edges, 0u);
  EXPECT_EQ(counts.faces, new_faces);  // the patch alone, not the model
  EXPECT_TRUE(counts.split);
  EXPECT_GT(counts.scale, 0.0);
  EXPECT_EQ(counts.dropped, 0u);
  std::size_t boundary_vertices = 0;
  for (const auto& loop : find_boundary_loops(c.input))
    boundary_vertices += loop.halfedges.size();
  EXPECT_GE(counts.sewn, boundary_vertices);
  // Each face: 14 bytes, n, a count and (n + 1)(n + 2) / 2 floats, n >= 1 on a new face.
  EXPECT_GE(counts.body, 16 * counts.vertices + (14 + 2 + 12) * counts.faces + 8 * counts.edges +
                             8 * counts.sewn + 4 * counts.dropped);
}

// A repair that is the holed input itself: an empty patch whose open edges are the hole's
// loop; nothing dropped.
TEST(ViewerMesh, NoPatchLeavesTheHoleOpen) {
  const Case c = generators::make_case("box/corner");
  const auto path = std::filesystem::temp_directory_path() / "viewer_mesh_no_patch.js";
  write_patch_mesh(c, c.input, path);
  const PlyCounts counts = read_counts(read_viewer_ply(path));
  EXPECT_EQ(counts.faces, 0u);
  EXPECT_GT(counts.edges, 2u);
  EXPECT_EQ(counts.dropped, 0u);
  EXPECT_EQ(counts.sewn, counts.vertices);  // every vertex of the loop is an input vertex
}

// File names: one case variant per case id, noise and seed; one patch per job.
TEST(ViewerMesh, FileNamesFollowTheJob) {
  harness::Job job;
  job.case_id = "cad/fandisk/edge/small";
  job.method_id = "liepa_cgal";
  job.noise_percent = 5;
  job.seed = 1;
  EXPECT_EQ(complete_mesh_file(job), "meshes/cad_fandisk_edge_small_5_1.complete.js");
  EXPECT_EQ(holed_mesh_file(job), "meshes/cad_fandisk_edge_small_5_1.holed.js");
  EXPECT_EQ(patch_mesh_file(job), "meshes/cad_fandisk_edge_small_liepa_cgal_no_user_5_1.patch.js");
}

}  // namespace
}  // namespace holebench::viewer
