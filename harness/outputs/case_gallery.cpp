#include "harness/outputs/case_gallery.h"

#include "core/geometry.h"
#include "core/labels_summary.h"
#include "harness/outputs/case_export.h"
#include "harness/outputs/file_names.h"
#include "harness/outputs/render/case_view.h"
#include "harness/results/markup_escape.h"

#include <fmt/format.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace holebench::harness {

std::filesystem::path write_case_gallery(const generators::CaseCatalog& catalog,
                                         const std::vector<generators::CaseDescriptor>& cases,
                                         const std::filesystem::path& dir,
                                         const GalleryOptions& options) {
  std::filesystem::create_directories(dir / "gallery");
  std::string cells;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const Case c = catalog.make(cases[i].id);
    const std::string file = "gallery/" + file_stem_of_id(c.id) + ".png";
    render::SnapshotOptions snapshot;
    snapshot.width = options.width;
    snapshot.height = options.height;
    const auto overlay = render::hole_overlay(c.input, 0.08 * bounding_box_diagonal(c.complete));
    render::write_png(render::render_snapshot(c.input, render::hole_camera(c), snapshot, overlay),
                      dir / file);
    cells += fmt::format(
        "<figure><img src=\"{}\" width=\"{}\" "
        "height=\"{}\"><figcaption><b>{}</b><br>{}</figcaption></figure>\n",
        file, options.width, options.height, xml_escape(c.id), xml_escape(labels_summary(c)));
    if (options.progress)
      std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, cases.size(), c.id.c_str());
  }
  const auto page = dir / "gallery.html";
  std::ofstream out(page);
  out << "<!doctype html>\n<html><head><meta charset=\"utf-8\"><title>holebench case "
         "gallery</title>\n"
         "<style>body{font-family:sans-serif;margin:1em}figure{display:inline-block;margin:6px;"
         "width:"
      << options.width
      << "px;vertical-align:top}figcaption{font-size:11px}</style></head><body>\n"
         "<h1>holebench case gallery</h1>\n<p>Each case's holed input: regions in colour, the hole "
         "boundary in red, transition vertices as dark dots, one face normal per region along the "
         "hole as a black stroke (as in figure 5 of the B-Rep paper). Labels come from the "
         "construction.</p>\n"
      << cells << "</body></html>\n";
  if (!out)
    throw std::runtime_error("cannot write " + page.string());
  return page;
}

}  // namespace holebench::harness
