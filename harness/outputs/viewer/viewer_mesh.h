// The meshes of the report's 3D viewer, written by the run beside the snapshots: per case
// (and noise level and seed) the complete and the holed mesh, per job the repaired one with
// its patch's distance to the complete model.
//
// Format: binary little-endian PLY, readable by MeshLab and the like:
//   element vertex N: float x, y, z; float quality (distance to the complete model relative
//     to its bounding-box diagonal; 0 on the vertices of kept faces)
//   element face M: list uchar int vertex_indices; uchar patch (1 on new faces)
//   element edge K: int vertex1, vertex2 (the open boundary edges: holes left open)
// and, in the repaired mesh, "comment heat_scale_max_rel_diag X": the case's heat scale
// (render/heat_map.h), the same for every method of the case; in the complete and holed
// meshes, the first hole's close-up camera (render/close_up.h's hole_view), where the viewer's
// camera starts: "comment view_direction X Y Z" (the direction it looks along), "comment
// view_target X Y Z" (the point it looks at), "comment view_distance D" (from the target) and
// "comment view_field_of_view_degrees A" (its full vertical angle).
// New faces are split into n x n smaller triangles with their own vertices (n from the
// face's longest edge, ViewerMeshOptions), so that a distance that peaks inside a face (a
// flat cap over a corner) shows: a colour interpolated from the patch's own vertices alone
// would be 0 there.
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
  int max_splits = 8;  ///< ...or into at most max_splits^2 pieces
};

/// The file names, relative to the output folder: meshes/<case variant>.complete.ply,
/// meshes/<case variant>.holed.ply and meshes/<job>.repaired.ply, where a case variant is
/// the case id, noise level and seed, and a job adds the method and the user ('/' and '|'
/// become '_').
std::string complete_mesh_file(const harness::Job& job);
std::string holed_mesh_file(const harness::Job& job);
std::string repaired_mesh_file(const harness::Job& job);

/// Writes a mesh without distances (every quality 0, every patch flag 0), with the first
/// hole's close-up camera in its header where one is given (comments view_direction,
/// view_target and view_distance: where the viewer's camera starts). The file appears
/// whole or not at all (written under a temporary name, then renamed), so that jobs of the
/// same case in parallel processes may write it at once. Throws std::runtime_error.
void write_plain_mesh(const Mesh& mesh, const std::filesystem::path& path,
                      const std::optional<render::Camera>& view = std::nullopt);

/// Writes the repaired mesh with its new faces split and coloured by distance to
/// `c.complete`; `complete_scene` (optional): an Embree scene of `c.complete` built by the
/// caller. Throws std::runtime_error.
void write_repaired_mesh(const Case& c, const Mesh& repaired, const std::filesystem::path& path,
                         const ViewerMeshOptions& options = {},
                         const embree::TriangleScene* complete_scene = nullptr);

/// Writes the three files of a job into out_dir (the complete and holed meshes only if
/// they are not there yet).
void write_job_meshes(const Case& c, const Mesh& repaired, const harness::Job& job,
                      const std::filesystem::path& out_dir, const ViewerMeshOptions& options = {},
                      const embree::TriangleScene* complete_scene = nullptr);

}  // namespace holebench::viewer
