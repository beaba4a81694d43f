// The meshes of the report's 3D viewer, written by the run beside the snapshots, by case and
// not by job: per case (and noise level and seed) the complete and the holed mesh once, per
// job its patch alone. The viewer assembles a job's repaired mesh in the page: the holed
// mesh without the faces the repair dropped, plus the job's patch.
//
// Each file is a script, so that the report's page loads it from file:// where it lies
// (no copy in the report): `holebenchViewer.receiveMesh("<file name>", "<base64>");`, the
// base64 of a gzip-compressed PLY. To get the PLY:
//   sed 's/.*, "\(.*\)");/\1/' meshes/X.js | base64 -d | gunzip > X.ply
// The PLY: binary little-endian, readable by MeshLab and the like:
//   element vertex N: float x, y, z; float quality (distance to the complete model relative
//     to its bounding-box diagonal; 0 on the vertices of kept faces)
//   element face M: list uchar int vertex_indices; uchar patch (1 on new faces)
//   element edge K: int vertex1, vertex2 (the open boundary edges: holes left open)
// and in a job's patch file two more face properties and two more elements:
//   face: uchar splits (n, 0 on faces that are not new); list uchar float split_quality (the
//     distances at the (n + 1)(n + 2) / 2 vertices of the face's split into n x n pieces,
//     vertex (i, j), i + j <= n, at c0 + (i (c1 - c0) + j (c2 - c0)) / n, row j by row, i
//     along the row; the viewer makes the pieces)
//   element sewn_vertex S: int vertex, int input_vertex (a patch vertex at the holed mesh's
//     vertex input_vertex: where the patch is sewn to the input)
//   element dropped_face D: int input_face (a face of the holed mesh the repair did not keep)
// The patch file holds the repaired mesh's faces that are not the input's own (the new faces,
// patch 1, and faces of the input the method changed, patch 0) and the repaired mesh's open
// edges; the repaired mesh is the holed mesh without the dropped faces plus these faces.
// In the patch file, "comment heat_scale_max_rel_diag X": the case's heat scale
// (render/heat_map.h), the same for every method of the case; in the complete and holed
// meshes, the first hole's close-up camera (render/close_up.h's hole_view), where the viewer's
// camera starts: "comment view_direction X Y Z" (the direction it looks along), "comment
// view_target X Y Z" (the point it looks at), "comment view_distance D" (from the target) and
// "comment view_field_of_view_degrees A" (its full vertical angle).
// New faces are drawn split into n x n smaller triangles (n from the face's longest edge,
// ViewerMeshOptions), each corner of a piece with its own distance, so that a distance that
// peaks inside a face (a flat cap over a corner) shows: a colour interpolated from the
// patch's own vertices alone would be 0 there. In the patch file the vertices carry their
// distances too.
#pragma once

#include "core/case.h"
#include "core/mesh.h"
#include "harness/outputs/render/snapshot.h"
#include "harness/results/record.h"

#include <filesystem>
#include <optional>
#include <string>

namespace holebench::embree {
class TriangleScene;
}

namespace holebench::viewer {

struct ViewerMeshOptions {
  /// New faces are split until their pieces' edges are at most this share of the diagonal...
  double target_edge_rel_diag = 0.01;
  int max_splits = 8;  ///< ...or into at most max_splits^2 pieces (at most 20)
};

/// The file names, relative to the output folder: meshes/<case variant>.complete.js,
/// meshes/<case variant>.holed.js and meshes/<job>.patch.js, where a case variant is the
/// case id, noise level and seed, and a job adds the method and the user ('/' and '|'
/// become '_').
std::string complete_mesh_file(const harness::Job& job);
std::string holed_mesh_file(const harness::Job& job);
std::string patch_mesh_file(const harness::Job& job);

/// The PLY inside a viewer file (the script's base64, decoded and decompressed). Throws
/// std::runtime_error when the file is not a viewer file.
std::string read_viewer_ply(const std::filesystem::path& path);

/// Writes a mesh without distances (every quality 0, every patch flag 0), with the first
/// hole's close-up camera in its header where one is given (comments view_direction,
/// view_target and view_distance: where the viewer's camera starts). The file appears
/// whole or not at all (written under a temporary name, then renamed), so that jobs of the
/// same case in parallel processes may write it at once. Throws std::runtime_error.
void write_plain_mesh(const Mesh& mesh, const std::filesystem::path& path,
                      const std::optional<render::Camera>& view = std::nullopt);

/// Writes the repair's patch against the holed mesh `c.input`: its faces that are not the
/// input's own, the new ones split and coloured by distance to `c.complete`, the open edges,
/// the vertices sewn to the input and the input faces dropped; `complete_scene` (optional):
/// an Embree scene of `c.complete` built by the caller. The work and the file grow with the
/// patch, not the model. Throws std::runtime_error.
void write_patch_mesh(const Case& c, const Mesh& repaired, const std::filesystem::path& path,
                      const ViewerMeshOptions& options = {},
                      const embree::TriangleScene* complete_scene = nullptr);

/// Writes the files of a job into out_dir: its patch, and the case's complete and holed
/// meshes if they are not there yet.
void write_job_meshes(const Case& c, const Mesh& repaired, const harness::Job& job,
                      const std::filesystem::path& out_dir, const ViewerMeshOptions& options = {},
                      const embree::TriangleScene* complete_scene = nullptr);

}  // namespace holebench::viewer
