#include "python/json_objects.h"

namespace py = pybind11;

namespace holebench::python {

py::object json_to_python(const nlohmann::ordered_json& document) {
  return py::module_::import("json").attr("loads")(document.dump());
}

}  // namespace holebench::python
