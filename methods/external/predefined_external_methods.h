// External methods holebench predefines: run by name (`--method meshlab_close_holes`, or a
// suite's "external_methods": [{"name": "meshlab_close_holes"}]), never as part of "every
// method" (each job starts a process).
#pragma once

#include "methods/external/external_method_spec.h"

#include <optional>
#include <string>
#include <vector>

namespace holebench {

/// meshlab_close_holes: MeshLab's Close Holes filter, `xvfb-run -a meshlabserver` with the
/// filter script methods/external/meshlab_close_holes.mlx of the source tree. MeshLab keeps
/// single-precision coordinates: its vertices are matched to the input's within 1e-6 of the
/// diagonal.
std::vector<ExternalMethodSpec> predefined_external_methods();

/// The predefined external method `name`, if there is one.
std::optional<ExternalMethodSpec> find_predefined_external_method(const std::string& name);

}  // namespace holebench
