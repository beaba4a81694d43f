// Meshes between NumPy and the core's types: a mesh is a dict {"vertices": (n, 3) float64,
// "faces": (m, 3) int, "regions": (m,) int (optional)}, a (vertices, faces[, regions]) tuple,
// or the path of a mesh file (OFF, OBJ, STL, PLY).
#pragma once

#include "core/mesh.h"
#include "core/mesh_builder.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace holebench::python {

/// The soup as a dict of new arrays: vertices (n, 3) float64, faces (m, 3) int32 and, where
/// the soup has them, regions (m,) int32.
pybind11::dict soup_to_dict(const TriangleSoup& soup);

/// A mesh given from Python as the file comment says, as a soup. `what` names the argument in
/// errors ("complete", "repaired"). Throws InvalidInputError (a ValueError in Python) for an
/// array of the wrong shape, an index out of range or a file that is not a mesh.
TriangleSoup soup_from_python(pybind11::handle mesh, const std::string& what);

/// The same, built into the core mesh with every check of build_mesh (manifold, oriented).
Mesh mesh_from_python(pybind11::handle mesh, const std::string& what);

}  // namespace holebench::python
