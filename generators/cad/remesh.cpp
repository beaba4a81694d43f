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
  PMP::isotropic_remeshing(faces(mesh), options.target_edge_length, mesh,
                           CGAL::parameters::number_of_iterations(options.iterations)
                               .edge_is_constrained_map(sharp)
                               .protect_constraints(false)
                               .relax_constraints(false));
  mesh.garbage_collection();
  try {
    return build_mesh(to_soup(mesh), BuildOptions{"remeshed model"});
  } catch (const InvalidInputError& e) {
    throw AlgorithmError(std::string("remeshing produced an invalid mesh: ") + e.what());
  }
}

}  // namespace holebench::generators
