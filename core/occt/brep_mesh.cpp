#include "core/occt/brep_mesh.h"

#include "core/occt/brep_file_reader.h"
#include "core/occt/isolated_read.h"
#include "core/occt/shape_tessellation.h"

#include <algorithm>
#include <mutex>
#include <string>

namespace holebench::occt {

const char* to_string(SurfaceType type) {
  switch (type) {
    case SurfaceType::Plane:
      return "plane";
    case SurfaceType::Cylinder:
      return "cylinder";
    case SurfaceType::Cone:
      return "cone";
    case SurfaceType::Sphere:
      return "sphere";
    case SurfaceType::Torus:
      return "torus";
    case SurfaceType::BSpline:
      return "bspline";
    case SurfaceType::Other:
      return "other";
  }
  return "other";
}

std::optional<BrepFormat> brep_format(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".step" || ext == ".stp")
    return BrepFormat::Step;
  if (ext == ".iges" || ext == ".igs")
    return BrepFormat::Iges;
  if (ext == ".brep" || ext == ".brp")
    return BrepFormat::Brep;
  return std::nullopt;
}

BrepMesh read_brep_mesh(const std::filesystem::path& path, const TessellationOptions& options) {
  // OpenCASCADE's STEP and IGES readers share static state: one file at a time.
  static std::mutex mutex;
  std::lock_guard<std::mutex> lock(mutex);
  // In a child process: a crash of OpenCASCADE on a damaged file is an InvalidInputError.
  TessellatedSoup tessellated = read_and_tessellate_isolated(path, options);
  BuildOptions build;
  build.source = path.string();
  BrepMesh result;
  result.face_surfaces = std::move(tessellated.face_surfaces);
  result.notes = std::move(tessellated.notes);
  result.mesh = build_mesh(tessellated.soup, build);
  return result;
}

}  // namespace holebench::occt
