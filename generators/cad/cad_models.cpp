#include "generators/cad/cad_models.h"

#include "core/boundary_loops.h"
#include "core/environment_path.h"
#include "core/errors.h"
#include "core/geometry.h"
#include "core/mesh_io.h"
#include "generators/cad/remesh.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <map>
#include <mutex>

#ifndef HOLEBENCH_DEFAULT_CAD_DIR
#define HOLEBENCH_DEFAULT_CAD_DIR ""
#endif

namespace holebench::generators {

std::filesystem::path default_cad_data_dir() {
  return environment_path_or("HOLEBENCH_CAD_DIR", HOLEBENCH_DEFAULT_CAD_DIR);
}

std::vector<CadModelSource> cgal_cad_models(const std::filesystem::path& data_dir) {
  const std::string cgal = "CGAL data set (CC0)";
  return {
      {"fandisk", data_dir / "fandisk.off", cgal + "; fandisk model by Hugues Hoppe"},
      {"anchor", data_dir / "anchor.off", cgal},
      {"pinion", data_dir / "pinion.off", cgal},
      {"couplingdown", data_dir / "couplingdown.off", cgal},
      {"oblong", data_dir / "oblong.off", cgal},
      {"part", data_dir / "part.off", cgal},
      {"joint", data_dir / "joint.off", cgal},
      {"turbine", data_dir / "turbine.off", cgal},
  };
}

std::vector<CadModelSource> user_mesh_sources(const std::vector<std::filesystem::path>& paths) {
  std::vector<CadModelSource> sources;
  auto is_mesh = [](const std::filesystem::path& p) {
    std::string ext = p.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    return ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply" ||
           occt::is_brep_file(p);
  };
  for (const auto& path : paths) {
    if (std::filesystem::is_directory(path)) {
      std::vector<std::filesystem::path> files;
      for (const auto& entry : std::filesystem::directory_iterator(path)) {
        if (entry.is_regular_file() && is_mesh(entry.path()))
          files.push_back(entry.path());
      }
      std::sort(files.begin(), files.end());
      for (const auto& file : files)
        sources.push_back({file.stem().string(), file, "user file"});
    } else {
      sources.push_back({path.stem().string(), path, "user file"});
    }
  }
  return sources;
}

ModelMesh read_model_mesh(const CadModelSource& source, const PrepareOptions& options) {
  ModelMesh read;
  read.brep = occt::is_brep_file(source.path);
  if (read.brep) {
    occt::BrepMesh brep_mesh = occt::read_brep_mesh(source.path, options.tessellation);
    read.mesh = std::move(brep_mesh.mesh);
    read.notes = std::move(brep_mesh.notes);
  } else {
    read.mesh = read_mesh(source.path);
  }
  return read;
}

std::shared_ptr<const AnalysedModel> prepare_cad_model(const CadModelSource& source,
                                                       const PrepareOptions& options) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const AnalysedModel>> cache;
  const std::string key =
      fmt::format("{}|{}|{}|{}|{}|{}|{}", source.path.string(), options.target_edge_length_rel_diag,
                  options.sharp_angle_degrees, options.tessellation.linear_deflection_rel_diag,
                  options.tessellation.angular_deflection_radians,
                  options.tessellation.sewing_tolerance_rel_diag,
                  fmt::join(options.tessellation.retry_deflection_factors, ","));
  {
    std::lock_guard<std::mutex> lock(mutex);
    if (auto it = cache.find(key); it != cache.end())
      return it->second;
  }
  // A B-Rep model's regions are its faces: they are kept through remeshing and used instead
  // of a segmentation, so its labels come from the B-Rep's faces.
  ModelMesh read = read_model_mesh(source, options);
  const bool brep = read.brep;
  Mesh& mesh = read.mesh;
  const auto loops = find_boundary_loops(mesh);
  if (!loops.empty()) {
    throw OpenMeshError(fmt::format("{}: the mesh is open ({} boundary loops); holes are "
                                    "punched into closed models only",
                                    source.path.string(), loops.size()),
                        std::make_shared<const ModelMesh>(std::move(read)));
  }
  RemeshOptions remesh;
  remesh.target_edge_length = options.target_edge_length_rel_diag * bounding_box_diagonal(mesh);
  remesh.sharp_angle_degrees = options.sharp_angle_degrees;
  remesh.keep_regions = brep;
  FeatureOptions features;
  features.segmentation.sharp_angle_degrees = options.sharp_angle_degrees;
  features.regions_from_mesh = brep;
  AnalysedModel analysed = analyse_model(source.name, remesh_isotropic(mesh, remesh), features);
  analysed.regions_are_brep_faces = brep;
  analysed.notes = std::move(read.notes);
  auto model = std::make_shared<const AnalysedModel>(std::move(analysed));
  std::lock_guard<std::mutex> lock(mutex);
  cache.emplace(key, model);
  return model;
}

}  // namespace holebench::generators
