// The case gallery: one picture per case in the manner of figure 5 of the B-Rep paper
// (region colours, hole boundary, transition vertices, face normals), on one HTML page.
#pragma once

#include "generators/case_catalog.h"

#include <filesystem>
#include <string>
#include <vector>

namespace holebench::harness {

struct GalleryOptions {
  int width = 360;
  int height = 270;
  bool progress = true;  ///< a line per case on stderr
};

/// Renders each case's holed input into `dir/gallery/<case>.png` and writes
/// `dir/gallery.html` with every picture and its labels. Returns the page's path.
std::filesystem::path write_case_gallery(const generators::CaseCatalog& catalog,
                                         const std::vector<generators::CaseDescriptor>& cases,
                                         const std::filesystem::path& dir,
                                         const GalleryOptions& options = {});

}  // namespace holebench::harness
