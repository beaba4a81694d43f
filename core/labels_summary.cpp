#include "core/labels_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

namespace holebench {

std::string labels_summary(const Case& c) {
  std::string text;
  for (const auto& hole : c.holes) {
    if (!text.empty())
      text += "; ";
    if (!hole.labels) {
      text += hole.target + (hole.unlabelled_because.empty()
                                 ? std::string(" (no labels)")
                                 : " (no labels: " + hole.unlabelled_because + ")");
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

namespace {

const char* combo_name(Convexity c) {
  return c == Convexity::Convex ? "convex" : "reflex";
}
const char* combo_name(BoundaryKind b) {
  return b == BoundaryKind::Inner ? "inner" : "outer";
}

template <typename T>
std::string sorted_join(const std::vector<T>& values) {
  std::vector<std::string> names;
  for (const auto& v : values)
    names.push_back(combo_name(v));
  std::sort(names.begin(), names.end());
  std::string out;
  for (const auto& n : names)
    out += (out.empty() ? "" : "-") + n;
  return out;
}

}  // namespace

std::string combo_of(const HoleLabels& labels) {
  std::string combo =
      fmt::format("k{}/{}", labels.k, labels.orientation == Orientation::Inner ? "inner" : "outer");
  if (labels.k == 2 && labels.transitions[0] == labels.transitions[1])
    combo += std::string("/") + combo_name(labels.transitions[0]);
  else if (labels.k >= 2)
    combo += "/" + sorted_join(labels.transitions);
  if (!labels.boundary_kinds.empty())
    combo += "/" + sorted_join(labels.boundary_kinds);
  return combo;
}

}  // namespace holebench
