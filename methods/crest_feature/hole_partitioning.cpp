#include "methods/crest_feature/hole_partitioning.h"

#include <algorithm>
#include <optional>

namespace holebench::crest_feature {
namespace {

// Splits `loop` by the chord (its first and last nodes are on the loop; the rest are new).
// Returns false (loop unchanged) where the chord's ends are not both on the loop or a part
// would have fewer than three nodes.
bool split(const std::vector<Node>& loop, const std::vector<Node>& chord, std::vector<Node>& first,
           std::vector<Node>& second) {
  const auto a = std::find(loop.begin(), loop.end(), chord.front());
  const auto b = std::find(loop.begin(), loop.end(), chord.back());
  if (a == loop.end() || b == loop.end() || a == b)
    return false;
  // Rotate so that the loop starts at the chord's start.
  std::vector<Node> rotated(a, loop.end());
  rotated.insert(rotated.end(), loop.begin(), a);
  const auto j = static_cast<std::size_t>(std::find(rotated.begin(), rotated.end(), chord.back()) -
                                          rotated.begin());
  // First: start .. end along the loop, back along the chord (reversed, inner nodes).
  first.assign(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(j) + 1);
  for (std::size_t k = chord.size() - 2; k >= 1; --k)
    first.push_back(chord[k]);
  // Second: end .. start along the loop, then along the chord.
  second.assign(rotated.begin() + static_cast<std::ptrdiff_t>(j), rotated.end());
  second.push_back(rotated.front());
  for (std::size_t k = 1; k + 1 < chord.size(); ++k)
    second.push_back(chord[k]);
  return first.size() >= 3 && second.size() >= 3;
}

}  // namespace

HolePartition partition_hole(const Hole& hole, const FeatureLines& lines) {
  HolePartition result;
  std::vector<Node> boundary;
  for (auto v : hole.vertices)
    boundary.push_back(v.idx());
  result.sub_holes.push_back(boundary);
  for (const auto& island : hole.islands) {
    std::vector<Node> nodes;
    for (auto v : island)
      nodes.push_back(v.idx());
    result.islands.push_back(std::move(nodes));
  }

  auto add_points = [&](const std::vector<Point>& points) {
    std::vector<Node> nodes;
    for (const Point& p : points) {
      nodes.push_back(new_point_node(static_cast<int>(result.new_points.size())));
      result.new_points.push_back(p);
    }
    return nodes;
  };
  auto vertex_node = [&](int loop_index) { return Node(hole.vertices[loop_index].idx()); };

  // The chords: one per pair; for each corner (the triple first), its first two lines make
  // one chord through the corner, each further line a chord from its feature point to the
  // corner; a corner link is a chord between two corners.
  std::vector<std::vector<Node>> chords;
  std::vector<std::vector<const FeatureLine*>> corner_lines(lines.corners.size());
  std::vector<const FeatureLine*> links;
  for (const auto& line : lines.lines) {
    if (line.from < 0) {
      links.push_back(&line);
      continue;
    }
    if (line.to < 0) {
      corner_lines[line.to_corner].push_back(&line);
      continue;
    }
    std::vector<Node> chord{vertex_node(line.from)};
    for (Node n : add_points(line.interior))
      chord.push_back(n);
    chord.push_back(vertex_node(line.to));
    chords.push_back(std::move(chord));
  }
  std::vector<std::optional<Node>> corner_node(lines.corners.size());
  for (std::size_t c = 0; c < lines.corners.size(); ++c) {
    const auto& at = corner_lines[c];
    if (at.size() < 2) {
      result.dropped.push_back("a corner with fewer than two feature lines");
      continue;
    }
    const Node corner = add_points({lines.corners[c]}).front();
    corner_node[c] = corner;
    std::vector<Node> through{vertex_node(at[0]->from)};
    for (Node n : add_points(at[0]->interior))
      through.push_back(n);
    through.push_back(corner);
    std::vector<Node> second = add_points(at[1]->interior);
    through.insert(through.end(), second.rbegin(), second.rend());
    through.push_back(vertex_node(at[1]->from));
    chords.push_back(std::move(through));
    for (std::size_t m = 2; m < at.size(); ++m) {
      std::vector<Node> further{vertex_node(at[m]->from)};
      for (Node n : add_points(at[m]->interior))
        further.push_back(n);
      further.push_back(corner);
      chords.push_back(std::move(further));
    }
  }
  for (const FeatureLine* link : links) {
    if (!corner_node[link->from_corner] || !corner_node[link->to_corner]) {
      result.dropped.push_back("a corner link to a corner that was left out");
      continue;
    }
    std::vector<Node> chord{*corner_node[link->from_corner]};
    for (Node n : add_points(link->interior))
      chord.push_back(n);
    chord.push_back(*corner_node[link->to_corner]);
    chords.push_back(std::move(chord));
  }

  for (const auto& chord : chords) {
    bool done = false;
    for (std::size_t i = 0; i < result.sub_holes.size() && !done; ++i) {
      std::vector<Node> first, second;
      if (!split(result.sub_holes[i], chord, first, second))
        continue;
      result.sub_holes[i] = std::move(first);
      result.sub_holes.push_back(std::move(second));
      done = true;
    }
    if (!done) {
      result.dropped.push_back("a feature line crosses another or leaves a degenerate sub-hole");
      continue;
    }
    for (std::size_t k = 1; k + 1 < chord.size(); ++k)
      result.feature_nodes.push_back(chord[k]);
  }
  return result;
}

}  // namespace holebench::crest_feature
