// The parts of the Python module `holebench`, each adding its functions to the module
// (module.cpp calls them in turn). docs/python.md describes the module for its users.
#pragma once

#include <pybind11/pybind11.h>

namespace holebench::python {

/// read_mesh, write_mesh: mesh files as NumPy arrays (mesh_arrays.cpp).
void bind_mesh_files(pybind11::module_& m);
/// suite, list_cases, make_case: the case catalog (case_bindings.cpp).
void bind_cases(pybind11::module_& m);
/// evaluate, evaluate_case: the metrics of a repaired mesh (evaluate_bindings.cpp).
void bind_evaluate(pybind11::module_& m);
/// read_results: a results file as rows (results_bindings.cpp).
void bind_results(pybind11::module_& m);

}  // namespace holebench::python
