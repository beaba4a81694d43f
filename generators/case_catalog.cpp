#include "generators/case_catalog.h"

#include "generators/box_holes.h"

#include <stdexcept>

namespace holebench::generators {
namespace {

struct CatalogEntry {
  CaseDescriptor descriptor;
  BoxHoleTarget target;
};

const std::vector<CatalogEntry>& catalog() {
  static const std::vector<CatalogEntry> entries = {
      {{"box/face_interior", "box", "face_interior",
        "box, hole in the interior of the +z face (k = 1, inner)"},
       BoxHoleTarget::FaceInterior},
      {{"box/edge", "box", "edge", "box, hole across the convex edge +y/+z (k = 2, inner)"},
       BoxHoleTarget::Edge},
      {{"box/corner", "box", "corner", "box, hole at the convex corner +x/+y/+z (k = 3, inner)"},
       BoxHoleTarget::Corner},
  };
  return entries;
}

}  // namespace

std::vector<CaseDescriptor> list_cases() {
  std::vector<CaseDescriptor> descriptors;
  for (const auto& entry : catalog())
    descriptors.push_back(entry.descriptor);
  return descriptors;
}

Case make_case(const std::string& id, std::uint64_t seed) {
  for (const auto& entry : catalog()) {
    if (entry.descriptor.id != id)
      continue;
    BoxHoleOptions options;
    options.target = entry.target;
    Case result = make_box_hole_case(options);
    // The skeleton's cases have no random element yet; the seed is recorded so that
    // noisy families keep the same contract (same id and seed, same bytes).
    result.seed = seed;
    return result;
  }
  throw std::invalid_argument("unknown case id '" + id + "' (see `holebench list`)");
}

}  // namespace holebench::generators
