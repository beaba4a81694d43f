#include "core/labels_summary.h"

#include <fmt/format.h>

namespace holebench {

std::string labels_summary(const Case& c) {
  std::string text;
  for (const auto& hole : c.holes) {
    if (!text.empty())
      text += "; ";
    if (!hole.labels) {
      text += hole.target + " (no labels)";
      continue;
    }
    const auto& l = *hole.labels;
    std::string transitions;
    for (auto t : l.transitions)
      transitions += std::string(transitions.empty() ? "" : ",") + to_string(t);
    std::string kinds;
    for (auto b : l.boundary_kinds)
      kinds += std::string(kinds.empty() ? "" : ",") + to_string(b);
    text += fmt::format("k={} {}", l.k, to_string(l.orientation));
    if (!transitions.empty())
      text += " [" + transitions + "]";
    if (!kinds.empty())
      text += " boundary " + kinds;
    if (l.linearly_dependent_faces)
      text += " parallel faces";
    text += fmt::format(" size {:.3g} vs {:.3g}: {}", l.size, l.structure_size,
                        to_string(l.expected_decision));
    if (!l.known_weak_spot.empty())
      text += " (weak spot: " + l.known_weak_spot + ")";
  }
  return text;
}

}  // namespace holebench
