// The Python module `holebench`: cases, the evaluation of repaired meshes and results files,
// with NumPy arrays in and out (docs/python.md).
#include "python/bindings.h"

PYBIND11_MODULE(holebench, m) {
  m.doc() =
      "holebench from Python: make the benchmark's cases (holed mesh, complete mesh, ground-truth "
      "labels), score a repaired mesh against a case or against any complete mesh with "
      "holebench's bounded distances, and read results files into rows. Meshes are dicts "
      "{'vertices': float64 (n, 3), 'faces': int (m, 3), 'regions': int (m,)}, (vertices, faces) "
      "tuples, or mesh file paths. See docs/python.md.";
  m.attr("__version__") = HOLEBENCH_PYTHON_VERSION;
  holebench::python::bind_mesh_files(m);
  holebench::python::bind_cases(m);
  holebench::python::bind_evaluate(m);
  holebench::python::bind_results(m);
}
