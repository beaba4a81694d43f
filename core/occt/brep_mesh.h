// B-Rep files (STEP, IGES, BREP) read through OpenCASCADE as one closed triangle mesh whose
// region ids are the B-Rep's face ids. This header names no OpenCASCADE type: the rest of
// holebench reads B-Rep files through it without seeing the library.
#pragma once

#include "core/mesh.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace holebench::occt {

/// The kind of surface a B-Rep face lies on.
enum class SurfaceType : std::uint8_t { Plane, Cylinder, Cone, Sphere, Torus, BSpline, Other };

/// "plane", "cylinder", "cone", "sphere", "torus", "bspline", "other".
const char* to_string(SurfaceType type);

enum class BrepFormat { Step, Iges, Brep };

/// The format a file name's extension names: .step/.stp, .iges/.igs, .brep/.brp (any case);
/// nothing for other extensions.
std::optional<BrepFormat> brep_format(const std::filesystem::path& path);

/// True if brep_format names a format: the files read_brep_mesh reads.
inline bool is_brep_file(const std::filesystem::path& path) {
  return brep_format(path).has_value();
}

struct TessellationOptions {
  /// BRepMesh_IncrementalMesh's linear deflection (the largest distance between a triangle
  /// and its face), relative to the bounding-box diagonal of the shape.
  double linear_deflection_rel_diag = 0.001;
  /// BRepMesh_IncrementalMesh's angular deflection: the largest angle in radians between the
  /// normals of a curved face across one triangle (0.35: at least 18 segments on a circle).
  double angular_deflection_radians = 0.35;
  /// Seconds that reading and tessellating one file may take (read_brep_mesh reads in a child
  /// process, which is stopped past it: OpenCASCADE loops on some damaged files); 0: none.
  double time_limit_seconds = 600.0;
  /// A shape with free edges (faces not sewn into a shell: core/occt/shape_sewing.h) is sewn
  /// with BRepBuilderAPI_Sewing at this tolerance, relative to the diagonal, before it is
  /// tessellated; 0: never sewn. 1e-4: edges exported apart by rounding (1e-6 to 1e-3 model
  /// units on parts of 10 to 1000 units) are joined, features larger than that are not.
  double sewing_tolerance_rel_diag = 1e-4;
  /// Where a face does not tessellate at the linear deflection above, the whole shape is
  /// tessellated again at the deflection times each of these factors in turn (finer first,
  /// then coarser); the first at which every face tessellates is kept, with a note.
  std::vector<double> retry_deflection_factors{0.25, 4.0};
};

/// A tessellated B-Rep: every triangle's region id is the id of the B-Rep face it lies on.
struct BrepMesh {
  /// Vertices shared along the B-Rep's edges, so one closed surface per closed shell.
  /// Every element is `Provenance::Original`.
  Mesh mesh;
  /// Per B-Rep face id (= region id, 0-based, in the order of TopExp::MapShapes): the type
  /// of its surface. A triangle's surface type is face_surfaces[region(mesh, f)].
  std::vector<SurfaceType> face_surfaces;
  /// What reading it took beyond the defaults, one line each: its faces sewn (with the free
  /// edges before and after), a deflection retried. Empty for a clean file.
  std::vector<std::string> notes;
};

/// Reads a STEP, IGES or BREP file (by extension), sews its faces where they are not sewn
/// (options.sewing_tolerance_rel_diag) and tessellates it (tessellate_shape).
/// Deterministic: the same file and options give the same mesh bit for bit.
/// Throws InvalidInputError with a one-line message naming the file: missing file, unknown
/// extension, a file OpenCASCADE cannot read as its format (with the read status), no faces,
/// a face that does not tessellate, a mesh that build_mesh rejects.
/// OpenCASCADE's console messages are silenced. The file is read in a child process
/// (core/occt/isolated_read.h): a crash of OpenCASCADE on a damaged file is an
/// InvalidInputError too.
BrepMesh read_brep_mesh(const std::filesystem::path& path, const TessellationOptions& options = {});

}  // namespace holebench::occt
