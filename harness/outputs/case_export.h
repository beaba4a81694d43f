// `holebench cases export`: each case as standard files, for people with other tools.
#pragma once

#include "core/case.h"

#include <filesystem>

namespace holebench::harness {

/// Writes into `dir` (created): input.ply and input.off (the holed mesh a method sees),
/// complete.ply and complete.off (the ground truth; PLY with a per-face "region" property),
/// and case.json (id, seed, noise, per hole: removed faces, missing edges and corners,
/// labels).
void export_case(const Case& c, const std::filesystem::path& dir);

}  // namespace holebench::harness
