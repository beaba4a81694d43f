// The report's 3D viewer script (viewer/viewer.js in the report folder): plain JavaScript
// for three.js r111 (the global THREE of three.min.js and its examples/js OrbitControls), no
// modules and no fetch, so that the page works offline and from a file:// URL.
#pragma once

namespace holebench::viewer {

/// The script's text. It reads the page's <script type="application/json"> elements
/// #viewer-config (colours) and #viewer-cases (the cases and their data files), loads a
/// case's meshes by adding a <script> element for its data file (which calls
/// holebenchViewer.receive), and draws the ticked meshes side by side.
const char* viewer_script();

}  // namespace holebench::viewer
