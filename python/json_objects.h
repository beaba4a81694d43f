// JSON documents of the harness (case.json, records) as Python objects.
#pragma once

#include <pybind11/pybind11.h>
#include <nlohmann/json.hpp>

namespace holebench::python {

/// `document` as Python dicts, lists, strings and numbers (through Python's json module:
/// numbers keep every digit, as in the files the harness writes).
pybind11::object json_to_python(const nlohmann::ordered_json& document);

}  // namespace holebench::python
