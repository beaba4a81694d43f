// evaluate and evaluate_case of the Python module: a repaired mesh scored against any complete
// mesh (what `holebench evaluate --complete` prints) or against a case's ground truth (what a
// run's record holds).
#include "core/errors.h"
#include "generators/case_catalog.h"
#include "harness/run/mesh_pair_evaluation.h"
#include "methods/external/output_patch.h"
#include "metrics/evaluation.h"
#include "python/bindings.h"
#include "python/json_objects.h"
#include "python/mesh_arrays.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <optional>
#include <string>

namespace py = pybind11;

namespace holebench::python {
namespace {

py::dict metrics_dict(const std::vector<MetricValue>& metrics) {
  py::dict values;
  for (const auto& metric : metrics)
    values[py::str(metric.name)] = metric.value;
  return values;
}

EvaluationOptions evaluation_options(double hausdorff_error_bound_rel_diag) {
  EvaluationOptions options;
  options.hausdorff_error_bound_rel_diag = hausdorff_error_bound_rel_diag;
  return options;
}

py::object evaluate_pair(py::handle complete, py::handle repaired, py::handle holed,
                         double hausdorff_error_bound_rel_diag) {
  const Mesh complete_mesh = mesh_from_python(complete, "complete");
  const TriangleSoup repaired_soup = soup_from_python(repaired, "repaired");
  std::optional<Mesh> holed_mesh;
  if (!holed.is_none())
    holed_mesh = mesh_from_python(holed, "holed");
  harness::MeshPairEvaluation pair;
  {
    py::gil_scoped_release release;
    pair = harness::evaluate_mesh_pair(complete_mesh, repaired_soup,
                                       holed_mesh ? &*holed_mesh : nullptr,
                                       evaluation_options(hausdorff_error_bound_rel_diag));
  }
  return json_to_python(harness::mesh_pair_to_json(pair, holed_mesh.has_value()));
}

py::list hole_reports(const std::vector<HoleReport>& holes) {
  py::list list;
  for (const auto& hole : holes) {
    py::dict entry;
    entry["loop_size"] = hole.loop_size;
    entry["closed"] = hole.closed;
    entry["new_faces"] = hole.new_faces;
    entry["new_vertices"] = hole.new_vertices;
    entry["note"] = hole.note;
    list.append(entry);
  }
  return list;
}

/// The case a dict of make_case names (id, seed, noise_percent), or a case id.
Case case_of(py::handle case_or_id, const std::vector<std::filesystem::path>& meshes) {
  std::string id;
  std::uint64_t seed = 0;
  double noise_percent = 0.0;
  if (py::isinstance<py::str>(case_or_id)) {
    id = case_or_id.cast<std::string>();
  } else if (py::isinstance<py::dict>(case_or_id)) {
    const auto dict = py::reinterpret_borrow<py::dict>(case_or_id);
    if (!dict.contains("id"))
      throw InvalidInputError("case: a case dict (make_case) needs 'id'");
    id = dict["id"].cast<std::string>();
    if (dict.contains("seed"))
      seed = dict["seed"].cast<std::uint64_t>();
    if (dict.contains("noise_percent"))
      noise_percent = dict["noise_percent"].cast<double>();
  } else {
    throw InvalidInputError("case: a case id or a dict of make_case");
  }
  generators::CatalogOptions options;
  options.user_meshes = meshes;
  return generators::CaseCatalog(options).make(id, seed, noise_percent);
}

py::dict evaluate_case(py::handle case_or_id, py::handle repaired,
                       const std::vector<std::filesystem::path>& meshes) {
  const Case c = case_of(case_or_id, meshes);
  const TriangleSoup repaired_soup = soup_from_python(repaired, "repaired");
  OutputPatch patch = recover_output_patch(c.input, repaired_soup);
  if (patch.input_faces_missing > 0) {
    throw InvalidInputError("repaired: " + std::to_string(patch.input_faces_missing) +
                            " of the input's " + std::to_string(c.input.n_faces()) +
                            " faces changed or dropped (they must come back unchanged: the same "
                            "vertex positions, bit for bit, and orientation)");
  }
  const MethodResult result = result_of_output_patch(std::move(patch));
  Evaluation evaluation;
  {
    py::gil_scoped_release release;
    evaluation = evaluate(c, result);
  }
  py::dict entry;
  entry["case_id"] = c.id;
  entry["seed"] = c.seed;
  entry["noise_percent"] = c.noise_percent;
  entry["status"] = to_string(result.status);
  entry["message"] = result.message;
  entry["holes"] = hole_reports(result.holes);
  entry["metrics"] = metrics_dict(evaluation.values);
  return entry;
}

}  // namespace

void bind_evaluate(py::module_& m) {
  m.def("evaluate", &evaluate_pair, py::arg("complete"), py::arg("repaired"),
        py::arg("holed") = py::none(), py::arg("hausdorff_error_bound_rel_diag") = 1e-4,
        "The metrics of `repaired` against `complete`, as `holebench evaluate --complete A "
        "--repaired B [--holed C] --json` prints them: a dict with "
        "complete_bounding_box_diagonal, metrics (name -> value: two-sided Hausdorff with its "
        "certified upper bound, mean/RMS intervals, the literature's sampled metrics, "
        "validity) and, with `holed` (the mesh the repair was made from), holes, "
        "removed_faces, new_faces and every hole-region metric; note says why `holed` was "
        "not used where it could not be. Meshes: dicts, (vertices, faces) tuples or paths.");
  m.def("evaluate_case", &evaluate_case, py::arg("case"), py::arg("repaired"),
        py::arg("meshes") = std::vector<std::filesystem::path>{},
        "Scores a repair of a case against its ground truth, as a run scores a method's "
        "result: `case` is a dict of make_case (its id, seed and noise_percent) or a case id; "
        "`repaired` the holed input with the patch added (the input's faces unchanged, in any "
        "order). Returns a dict: case_id, seed, noise_percent, status ('ok', 'partial', "
        "'failed': holes closed), message, holes (per boundary loop of the input: loop_size, "
        "closed, new_faces, new_vertices), metrics (named as in a run's records).");
}

}  // namespace holebench::python
