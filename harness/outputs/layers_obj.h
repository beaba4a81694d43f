// A method's layers (core/method_layers.h) as one Wavefront OBJ file, a group per layer
// (`g NAME`): points as `p`, polylines as `l`, surfaces as `f`, for any 3D viewer
// (`holebench run --layers`). Coordinates are written to 17 significant digits.
#pragma once

#include "core/method_layers.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

/// The OBJ text of `layers`.
std::string layers_obj(const std::vector<MethodLayer>& layers);

/// Writes layers_obj(layers) to `path` (atomically).
void write_layers_obj(const std::vector<MethodLayer>& layers, const std::filesystem::path& path);

}  // namespace holebench::harness
