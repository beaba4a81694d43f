#include "methods/slice_loft/slice_loft_variants.h"

namespace holebench::slice_loft {

const std::vector<Departure>& departures() {
  static const std::vector<Departure> list{
      {"wide_sections",
       "sections over every slice piece of the influencing area (margin at least 3 mean "
       "edges, ends traced 2 edges beyond, 2 slices beyond each end) instead of from "
       "boundary to boundary",
       [](SliceLoftOptions& o) {
         o.surface.extent = SectionExtent::InfluencingArea;
         o.surface.extra_slices = 2;
         o.identification.min_influence_margin_edges = 3.0;
       }},
      {"both_end_tracing", "gaps traced from both ends and blended instead of from one end",
       [](SliceLoftOptions& o) { o.surface.tracing = GapTracing::BothEnds; }},
      {"major_axis",
       "slicing along the major axis of the portion's boundary instead of its box's longer "
       "edge",
       [](SliceLoftOptions& o) { o.surface.direction = SlicingDirection::MajorAxis; }},
      {"plane_trimming",
       "trimming in the portion's plane first instead of the surface's own domain",
       [](SliceLoftOptions& o) { o.tessellation.plane_first = true; }},
  };
  return list;
}

SliceLoftOptions plus_options(bool direct) {
  SliceLoftOptions options;
  options.tessellation.direct = direct;
  for (const Departure& departure : departures())
    departure.apply(options);
  return options;
}

std::vector<SliceLoftMethod> named_variants() {
  return {
      SliceLoftMethod(plus_options(false), "slice_loft_plus",
                      "slice_loft with every departure of the project (wide sections, both-end "
                      "tracing, major-axis slicing, plane trimming first): docs/slice_loft.md"),
      SliceLoftMethod(plus_options(true), "slice_direct_plus",
                      "slice_direct with the same departures as slice_loft_plus"),
  };
}

std::vector<SliceLoftMethod> ablation_methods() {
  std::vector<SliceLoftMethod> methods;
  for (bool direct : {false, true}) {
    for (const Departure& departure : departures()) {
      SliceLoftOptions options;
      options.tessellation.direct = direct;
      departure.apply(options);
      const std::string base = direct ? "slice_direct" : "slice_loft";
      methods.emplace_back(options, base + "_with_" + departure.name,
                           "Table 2 ablation: " + base + " with " + departure.what);
    }
  }
  return methods;
}

}  // namespace holebench::slice_loft
