// The real CAD meshes: CGAL's data set (Debian package libcgal-demo, CC0) and a user's own
// mesh files, prepared for punching (closed check, isotropic remeshing, segmentation).
#pragma once

#include "core/errors.h"
#include "core/occt/brep_mesh.h"
#include "generators/punch_targets.h"

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace holebench::generators {

struct CadModelSource {
  std::string name;  ///< e.g. "fandisk"; for user files the file stem
  std::filesystem::path path;
  std::string credit;
};

/// The folder with the CGAL data set's meshes: $HOLEBENCH_CAD_DIR if set, else the folder
/// the build extracted them to (from /usr/share/doc/libcgal-dev/data.tar.gz).
std::filesystem::path default_cad_data_dir();

/// The CGAL data set's CAD models holebench uses, in a fixed order (whether or not the
/// files exist: a missing one is reported when it is prepared).
std::vector<CadModelSource> cgal_cad_models(const std::filesystem::path& data_dir);

/// Model files named by a user: files (meshes: OFF, OBJ, STL, PLY; B-Rep models: STEP, IGES,
/// BREP) or folders (every such file in it, sorted by name).
std::vector<CadModelSource> user_mesh_sources(const std::vector<std::filesystem::path>& paths);

struct PrepareOptions {
  double target_edge_length_rel_diag = 0.01;  ///< remeshing target, relative to the diagonal
  double sharp_angle_degrees = 30.0;
  occt::TessellationOptions tessellation;  ///< for B-Rep files (STEP, IGES, BREP)
};

/// A model file as read, before any check or remeshing: a B-Rep file by occt::read_brep_mesh
/// (with its notes: faces sewn, a deflection retried), a mesh file by read_mesh.
struct ModelMesh {
  Mesh mesh;
  std::vector<std::string> notes;
  bool brep = false;
};
ModelMesh read_model_mesh(const CadModelSource& source, const PrepareOptions& options = {});

/// prepare_cad_model's error for an open mesh: its holes are real holes (generators/real_holes.h),
/// which the catalog makes cases of instead of punching. It carries the mesh as read, so that
/// the file is not read again for them.
class OpenMeshError : public InvalidInputError {
 public:
  OpenMeshError(const std::string& message, std::shared_ptr<const ModelMesh> read)
      : InvalidInputError(message), read_(std::move(read)) {}
  const std::shared_ptr<const ModelMesh>& read() const { return read_; }

 private:
  std::shared_ptr<const ModelMesh> read_;
};

/// Reads (a B-Rep file by occt::read_brep_mesh, a mesh file by read_mesh), checks (closed: holes
/// are punched into complete models) and remeshes a model, then segments it and finds its
/// features. A B-Rep model is not segmented: its faces, kept through the remeshing, are its
/// regions. Throws OpenMeshError for an open mesh and InvalidInputError with the reason for a
/// missing, non-manifold or degenerate one. Results are cached per path and options for the
/// process, so listing and making cases analyse each model once.
std::shared_ptr<const AnalysedModel> prepare_cad_model(const CadModelSource& source,
                                                       const PrepareOptions& options = {});

}  // namespace holebench::generators
