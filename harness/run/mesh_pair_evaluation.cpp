#include "harness/run/mesh_pair_evaluation.h"

#include "core/case.h"
#include "core/errors.h"
#include "core/features.h"
#include "core/geometry.h"
#include "generators/missing_sharp_edges.h"
#include "methods/external/output_patch.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <numeric>
#include <set>
#include <string_view>

namespace holebench::harness {

namespace {

// A face by its three corner points, in an order of their own (so any rotation or
// orientation of the same triangle is the same key).
using FaceKey = std::array<std::array<double, 3>, 3>;

FaceKey face_key(const Mesh& mesh, FaceHandle f) {
  FaceKey key{};
  const auto ids = triangle_vertex_indices(mesh, f);
  for (int k = 0; k < 3; ++k) {
    const Point& p = mesh.point(VertexHandle(ids[k]));
    key[k] = {p[0], p[1], p[2]};
  }
  std::sort(key.begin(), key.end());
  return key;
}

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i)
    i = parent[i] = parent[parent[i]];
  return i;
}

// The complete mesh's faces the holed mesh lacks, as holes: one per set of them connected
// through shared vertices, with their missing sharp edges and corners.
std::vector<HoleTruth> holes_of(const Mesh& complete, const Mesh& holed) {
  std::set<FaceKey> kept;
  for (const auto f : holed.faces())
    kept.insert(face_key(holed, f));
  std::vector<char> removed(complete.n_faces(), 0);
  std::vector<int> parent(complete.n_faces());
  std::iota(parent.begin(), parent.end(), 0);
  std::vector<int> face_of_vertex(complete.n_vertices(), -1);
  for (const auto f : complete.faces()) {
    if (kept.count(face_key(complete, f)))
      continue;
    removed[f.idx()] = 1;
    for (const int v : triangle_vertex_indices(complete, f)) {
      if (face_of_vertex[v] >= 0)
        parent[find_root(parent, f.idx())] = find_root(parent, face_of_vertex[v]);
      else
        face_of_vertex[v] = f.idx();
    }
  }
  std::vector<HoleTruth> holes;
  std::vector<int> hole_of_root(complete.n_faces(), -1);
  for (int f = 0; f < static_cast<int>(complete.n_faces()); ++f) {
    if (!removed[f])
      continue;
    const int root = find_root(parent, f);
    if (hole_of_root[root] < 0) {
      hole_of_root[root] = static_cast<int>(holes.size());
      holes.emplace_back();
      holes.back().target = "hole";
      holes.back().unlabelled_because = "a hole of a mesh pair (no labels)";
    }
    holes[hole_of_root[root]].removed_faces.push_back(f);
  }
  const FeatureAnalysis features = analyse_features(complete);
  for (auto& hole : holes) {
    std::vector<char> mine(complete.n_faces(), 0);
    for (const int f : hole.removed_faces)
      mine[f] = 1;
    hole.missing_edges =
        generators::missing_sharp_edges(complete, mine, generators::FeatureChainEdges{features});
    hole.missing_corners = generators::missing_corners(complete, mine, features);
  }
  return holes;
}

// The metrics a pair of meshes has: not the hole reports' (classification, arrows, fallbacks,
// defects), which a mesh alone does not make, nor the method's time.
bool applies_to_a_pair(const std::string& name, bool with_holed) {
  for (const std::string_view prefix :
       {"classification_", "decision_", "arrow", "fallback_", "defect_", "time_"}) {
    if (name.rfind(prefix, 0) == 0)
      return false;
  }
  if (with_holed)
    return true;
  // Without the holed mesh there is no hole: nothing of a patch, of a hole region or of the
  // input's faces.
  for (const std::string_view prefix :
       {"hole_", "patch_", "new_", "missing_", "original_faces", "input_faces", "valid_repair"}) {
    if (name.rfind(prefix, 0) == 0)
      return false;
  }
  return true;
}

}  // namespace

MeshPairEvaluation evaluate_mesh_pair(const Mesh& complete, const TriangleSoup& repaired,
                                      const Mesh* holed, const EvaluationOptions& options) {
  if (complete.n_faces() == 0)
    throw InvalidInputError("the complete mesh has no faces");
  MeshPairEvaluation pair;
  pair.diagonal = bounding_box_diagonal(complete);
  Case c;
  c.id = "pair";
  c.family = "pair";
  c.kind = "pair";
  c.complete = complete;
  MethodResult result;
  bool with_holed = false;
  if (holed) {
    OutputPatch patch = recover_output_patch(*holed, repaired);
    std::vector<HoleTruth> holes;
    std::size_t removed = 0;
    if (patch.input_faces_missing == 0) {
      holes = holes_of(complete, *holed);
      for (const auto& hole : holes)
        removed += hole.removed_faces.size();
    }
    if (patch.input_faces_missing == 0 && 2 * removed >= complete.n_faces()) {
      // A holed mesh whose points moved (noise) shares no face with the complete one: every
      // face would be "removed", and the hole region the whole model.
      pair.note = "the holed mesh shares " + std::to_string(complete.n_faces() - removed) +
                  " of the complete mesh's " + std::to_string(complete.n_faces()) +
                  " faces (a noisy input?); the holes are found only where its faces are the "
                  "complete mesh's, bit for bit; measured without it";
    } else if (patch.input_faces_missing == 0) {
      with_holed = true;
      c.input = *holed;
      c.holes = std::move(holes);
      pair.holes = c.holes.size();
      pair.removed_faces = removed;
      pair.new_faces = patch.new_faces;
      result = result_of_output_patch(std::move(patch));
    } else {
      pair.note = "the repaired mesh changed or dropped " +
                  std::to_string(patch.input_faces_missing) +
                  " faces of the holed mesh; measured without it";
    }
  }
  if (!with_holed) {
    // The repaired mesh alone: every face its own, none new.
    c.input = build_mesh(repaired);
    result.repaired = c.input;
  }
  const Evaluation evaluation = evaluate(c, result, options);
  for (const auto& metric : evaluation.values) {
    if (applies_to_a_pair(metric.name, with_holed))
      pair.metrics.push_back(metric);
  }
  return pair;
}

nlohmann::ordered_json mesh_pair_to_json(const MeshPairEvaluation& pair, bool with_holed) {
  nlohmann::ordered_json j;
  if (with_holed) {
    j["holes"] = pair.holes;
    j["removed_faces"] = pair.removed_faces;
    j["new_faces"] = pair.new_faces;
  }
  j["complete_bounding_box_diagonal"] = pair.diagonal;
  if (!pair.note.empty())
    j["note"] = pair.note;
  auto& metrics = j["metrics"] = nlohmann::ordered_json::object();
  for (const auto& metric : pair.metrics)
    metrics[metric.name] = metric.value;
  return j;
}

}  // namespace holebench::harness
