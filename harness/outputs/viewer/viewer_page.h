// The 3D viewer of `holebench report`: per case (and noise level and seed) the complete,
// holed and repaired meshes, drawn with three.js in report.html, with orbit controls, a tick
// box per mesh and the pictures' error colouring. A repaired mesh is assembled in the page
// from the case's holed mesh and the job's patch (viewer_mesh.h).
//
// Copied into report/viewer/: three.js r111 (Debian's libjs-three: three.min.js and
// examples/js/controls/OrbitControls.js) and the viewer's script. The meshes are not copied:
// the page links the run's files (meshes/*.js, scripts that hand their PLY to the page, loaded
// by a <script> element when the case is chosen), so the page works offline and from file://
// as long as the report stays beside the run's meshes/ folder.
#pragma once

#include "harness/results/results_reader.h"

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace holebench::viewer {

struct ViewerOptions {
  /// Where three.js is installed; empty: $HOLEBENCH_THREE_DIR, else
  /// /usr/share/javascript/three (Debian's libjs-three).
  std::filesystem::path three_dir;
  std::size_t max_cases = 500;  ///< cases beyond it are left out of the viewer (said on the page)
};

struct ViewerSection {
  std::string html;                ///< the section of report.html (with its scripts)
  std::vector<std::string> files;  ///< written, relative to the report folder
  std::string note;                ///< why there is no viewer; empty when there is one
  std::size_t cases = 0;           ///< cases in the viewer
};

/// The three.js folder that options name.
std::filesystem::path three_dir(const ViewerOptions& options);

/// Writes report_dir/viewer/ for the records of `data` whose meshes are in results_dir/meshes/
/// (linked, not copied) and returns the page's section. Without meshes or without three.js the
/// section says why. Throws std::runtime_error when a file cannot be written.
ViewerSection write_viewer(const harness::ResultsData& data,
                           const std::filesystem::path& results_dir,
                           const std::filesystem::path& report_dir,
                           const ViewerOptions& options = {});

}  // namespace holebench::viewer
