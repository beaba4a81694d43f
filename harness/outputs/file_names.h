// The one rule for naming a file after an id: snapshots and viewer meshes (job ids), exported
// cases and gallery pictures (case ids).
#pragma once

#include <string>

namespace holebench::harness {

/// The file name, without extension, of an id such as a case id ("brep/k2/inner/convex") or a
/// job id ("box/corner|liepa_cgal|no_user|0|0"): each '/' and '|' becomes '_'.
std::string file_stem_of_id(std::string id);

}  // namespace holebench::harness
