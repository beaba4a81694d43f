// The generators' only CGAL translation unit for remeshing.
#include "generators/cad/remesh.h"

#include "core/errors.h"
#include "core/mesh_builder.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <boost/property_map/property_map.hpp>

#include <map>

namespace holebench::generators {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

// The mesh's own region ids as CGAL's face patch map, read and written in place: a face CGAL
// adds takes its patch's id, and the ids move with the faces in garbage collection.
struct RegionPatchMap {
  using key_type = boost::graph_traits<Mesh>::face_descriptor;
  using value_type = int;
  using reference = int;
  using category = boost::read_write_property_map_tag;
  Mesh* mesh;
  friend int get(const RegionPatchMap& map, key_type f) { return region(*map.mesh, f); }
  friend void put(const RegionPatchMap& map, key_type f, int id) { set_region(*map.mesh, f, id); }
};

}  // namespace

Mesh remesh_isotropic(const Mesh& input, const RemeshOptions& options) {
  Mesh mesh = input;
  // An associative map: OpenMesh's bool properties are std::vector<bool> proxies, which
  // CGAL's property map wrapper cannot return by reference.
  using Edge = boost::graph_traits<Mesh>::edge_descriptor;
  std::map<Edge, bool> sharp_edges;
  boost::associative_property_map<std::map<Edge, bool>> sharp(sharp_edges);
  for (auto e : edges(mesh))
    put(sharp, e, false);
  PMP::detect_sharp_edges(mesh, options.sharp_angle_degrees, sharp);
  const auto parameters = CGAL::parameters::number_of_iterations(options.iterations)
                              .edge_is_constrained_map(sharp)
                              .protect_constraints(false)
                              .relax_constraints(false);
  if (options.keep_regions) {
    for (auto e : edges(mesh)) {
      const auto h = halfedge(e, mesh);
      if (!CGAL::is_border_edge(h, mesh) &&
          region(mesh, face(h, mesh)) != region(mesh, face(opposite(h, mesh), mesh))) {
        put(sharp, e, true);
      }
    }
    PMP::isotropic_remeshing(faces(mesh), options.target_edge_length, mesh,
                             parameters.face_patch_map(RegionPatchMap{&mesh}));
  } else {
    PMP::isotropic_remeshing(faces(mesh), options.target_edge_length, mesh, parameters);
  }
  mesh.garbage_collection();
  try {
    return build_mesh(to_soup(mesh), BuildOptions{"remeshed model"});
  } catch (const InvalidInputError& e) {
    throw AlgorithmError(std::string("remeshing produced an invalid mesh: ") + e.what());
  }
}

}  // namespace holebench::generators
