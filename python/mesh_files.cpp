// read_mesh and write_mesh of the Python module: mesh files as NumPy arrays.
#include "core/mesh_io.h"
#include "python/bindings.h"
#include "python/mesh_arrays.h"

namespace py = pybind11;

namespace holebench::python {

void bind_mesh_files(py::module_& m) {
  m.def(
      "read_mesh", [](const std::string& path) { return soup_to_dict(read_soup(path)); },
      py::arg("path"),
      "Reads a mesh file (OFF, OBJ, STL, PLY; polygons split into fans) into a dict "
      "{'vertices': float64 (n, 3), 'faces': int32 (m, 3)[, 'regions': int32 (m,)]}.");
  m.def(
      "write_mesh",
      [](const std::string& path, py::handle mesh, bool binary) {
        WriteOptions options;
        options.binary = binary;
        write_mesh(mesh_from_python(mesh, "mesh"), path, options);
      },
      py::arg("path"), py::arg("mesh"), py::arg("binary") = true,
      "Writes a mesh (a dict, a (vertices, faces) tuple) in the format of the path's extension; "
      "the mesh must be manifold and consistently oriented. PLY keeps the regions.");
}

}  // namespace holebench::python
