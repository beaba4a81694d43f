// suite, list_cases and make_case of the Python module: the case catalog, as `holebench cases`
// and `holebench run` see it.
#include "generators/case_catalog.h"
#include "harness/outputs/case_export.h"
#include "harness/run/case_pattern.h"
#include "harness/run/case_selection.h"
#include "harness/run/suite.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/mesh_arrays.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <filesystem>
#include <string>
#include <vector>

namespace py = pybind11;

namespace holebench::python {
namespace {

generators::CatalogOptions catalog_options(const std::vector<std::string>& patterns,
                                           bool include_cad,
                                           const std::vector<std::filesystem::path>& meshes) {
  generators::CatalogOptions options;
  options.include_cad = include_cad;
  options.user_meshes = meshes;
  options.families = harness::families_of_patterns(patterns);
  return options;
}

py::list descriptors_to_list(const std::vector<generators::CaseDescriptor>& cases) {
  py::list list;
  for (const auto& descriptor : cases) {
    py::dict entry;
    entry["id"] = descriptor.id;
    entry["family"] = descriptor.family;
    entry["kind"] = descriptor.kind;
    entry["description"] = descriptor.description;
    list.append(entry);
  }
  return list;
}

py::list list_cases(const std::vector<std::string>& patterns, bool include_cad,
                    const std::vector<std::filesystem::path>& meshes) {
  const std::vector<std::string> selection =
      patterns.empty() ? std::vector<std::string>{"*"} : patterns;
  const generators::CaseCatalog catalog(catalog_options(selection, include_cad, meshes));
  return descriptors_to_list(harness::select_cases(catalog, selection));
}

py::dict suite(const std::string& name) {
  const harness::Suite loaded = harness::load_suite(name);
  py::dict entry;
  entry["name"] = loaded.name;
  entry["description"] = loaded.description;
  entry["case_patterns"] = loaded.case_patterns;
  const generators::CaseCatalog catalog(
      catalog_options(loaded.case_patterns, loaded.include_cad, loaded.meshes));
  py::list ids;
  for (const auto& descriptor : harness::select_cases(catalog, loaded.case_patterns))
    ids.append(descriptor.id);
  entry["cases"] = ids;
  entry["methods"] = loaded.methods;
  entry["users"] = loaded.users;
  entry["noise_percent"] = loaded.noise_levels;
  entry["seeds"] = loaded.seeds;
  entry["include_cad"] = loaded.include_cad;
  return entry;
}

py::dict make_case(const std::string& id, std::uint64_t seed, double noise_percent,
                   const std::vector<std::filesystem::path>& meshes) {
  generators::CatalogOptions options;
  options.user_meshes = meshes;
  const generators::CaseCatalog catalog(options);
  const Case c = catalog.make(id, seed, noise_percent);
  py::dict entry = json_to_python(harness::case_to_json(c));
  entry["input"] = soup_to_dict(to_soup(c.input));
  entry["complete"] = soup_to_dict(to_soup(c.complete));
  return entry;
}

}  // namespace

void bind_cases(py::module_& m) {
  m.def("suite", &suite, py::arg("name"),
        "A suite of suites/ (or a suite file's path) as a dict: name, description, "
        "case_patterns, cases (the case ids its patterns select, in catalog order), methods, "
        "users, noise_percent, seeds, include_cad.");
  m.def("list_cases", &list_cases, py::arg("patterns") = std::vector<std::string>{},
        py::arg("include_cad") = true, py::arg("meshes") = std::vector<std::filesystem::path>{},
        "The catalog's cases matching any of the id patterns ('*' any run of characters, '?' "
        "one; none: every case), as dicts {id, family, kind, description}, in catalog order. "
        "include_cad lists CGAL's CAD models (analysed on first use: seconds); meshes adds "
        "the user's mesh or B-Rep files (file/<stem>/... cases).");
  m.def("make_case", &make_case, py::arg("id"), py::arg("seed") = 0, py::arg("noise_percent") = 0.0,
        py::arg("meshes") = std::vector<std::filesystem::path>{},
        "Makes case `id` as every run does (the same id, seed and noise give the same case bit "
        "for bit): a dict with id, family, kind, seed, noise_percent, "
        "complete_bounding_box_diagonal, holes (per hole: target, removed_faces, missing_edges, "
        "missing_corners, labels: the ground truth), input (the holed mesh a method sees) and "
        "complete (the ground truth), each {'vertices', 'faces', 'regions'}.");
}

}  // namespace holebench::python
