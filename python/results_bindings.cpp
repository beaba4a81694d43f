// read_results of the Python module: a results file as flat rows (one dict per record), which
// pandas.DataFrame takes as they are.
#include "harness/results/results_reader.h"
#include "python/bindings.h"

#include <pybind11/stl/filesystem.h>

#include <filesystem>

namespace py = pybind11;

namespace holebench::python {
namespace {

py::dict record_row(const harness::JobRecord& record) {
  py::dict row;
  row["job_id"] = record.job.id();
  row["case_id"] = record.job.case_id;
  row["method"] = record.job.method_id;
  row["user"] = record.job.user;
  row["noise_percent"] = record.job.noise_percent;
  row["seed"] = record.job.seed;
  row["case_family"] = record.case_family;
  row["case_kind"] = record.case_kind;
  row["status"] = harness::to_string(record.status);
  row["message"] = record.message;
  row["method_seconds"] = record.method_seconds;
  std::size_t closed = 0;
  std::size_t fallbacks = 0;
  for (const auto& hole : record.holes) {
    closed += hole.closed ? 1 : 0;
    fallbacks += hole.fallback.empty() ? 0 : 1;
  }
  row["holes"] = record.holes.size();
  row["holes_closed"] = closed;
  row["holes_with_fallback"] = fallbacks;
  for (const auto& metric : record.metrics)
    row[py::str(metric.name)] = metric.value;
  return row;
}

py::list read_results(const std::filesystem::path& path) {
  const std::filesystem::path file =
      std::filesystem::is_directory(path) ? path / "results.json" : path;
  const harness::ResultsData data = harness::read_results_json(file);
  py::list rows;
  for (const auto& record : data.records)
    rows.append(record_row(record));
  return rows;
}

}  // namespace

void bind_results(py::module_& m) {
  m.def("read_results", &read_results, py::arg("path"),
        "Reads a results.json (or a run's output folder holding one) into a list of rows, one "
        "dict per record: job_id, case_id, method, user, noise_percent, seed, case_family, "
        "case_kind, status, message, method_seconds, holes, holes_closed, holes_with_fallback, "
        "then every metric by name (a record without a metric has no key for it). "
        "pandas.DataFrame(rows) takes them as they are.");
}

}  // namespace holebench::python
