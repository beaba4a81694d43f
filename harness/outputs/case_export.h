// `holebench cases export`: each case as standard files, for people with other tools.
#pragma once

#include "core/case.h"

#include <nlohmann/json_fwd.hpp>

#include <filesystem>

namespace holebench::harness {

/// Writes into `dir` (created): input.ply and input.off (the holed mesh a method sees),
/// complete.ply and complete.off (the ground truth; PLY with a per-face "region" property),
/// and case.json (id, seed, noise, per hole: removed faces, missing edges and corners,
/// labels).
void export_case(const Case& c, const std::filesystem::path& dir);

/// What case.json says of a case (the file names aside): id, family, kind, seed, noise, the
/// complete model's diagonal and per hole its ground truth (target, removed faces, missing
/// edges and corners, labels or null).
nlohmann::ordered_json case_to_json(const Case& c);

}  // namespace holebench::harness
