#include "generators/crease_holes.h"

#include "generators/punched_case.h"
#include "generators/random.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

namespace holebench::generators {
namespace {

// Per vertex, the distance to each chain (over the chain's vertices: chains are sampled at
// the remeshing's edge length, 1 % of the diagonal).
double distance_to_chain(const Mesh& mesh, const Point& p, const SharpEdgeChain& chain) {
  double best = std::numeric_limits<double>::infinity();
  for (auto v : chain.vertices)
    best = std::min(best, (mesh.point(v) - p).norm());
  return best;
}

}  // namespace

std::optional<CreaseTarget> find_crease_target(const AnalysedModel& model, int creases,
                                               const CreaseHoleOptions& options) {
  const Mesh& mesh = model.mesh;
  const auto& chains = model.features.chains;
  for (double radius_rel : options.radii_rel_diag) {
    const double r = radius_rel * model.diagonal;
    const double inner = (1.0 - options.irregularity) * r;  // the hole surely reaches this far
    const double outer = (1.0 + options.irregularity) * r + 0.01 * model.diagonal;
    std::optional<CreaseTarget> best;
    double best_score = 0.0;
    auto consider = [&](VertexHandle v) {
      const Point p = mesh.point(v);
      int in = 0;
      double farthest_in = 0.0, nearest_other = std::numeric_limits<double>::infinity();
      for (const auto& chain : chains) {
        const double d = distance_to_chain(mesh, p, chain);
        if (d <= 0.6 * inner) {
          ++in;
          farthest_in = std::max(farthest_in, d);
          // A crossing chain does not end inside the hole (n = 1, 2).
          if (creases < 3 && !chain.closed &&
              (std::min((mesh.point(chain.vertices.front()) - p).norm(),
                        (mesh.point(chain.vertices.back()) - p).norm()) <= outer))
            return;
        } else {
          nearest_other = std::min(nearest_other, d);
        }
      }
      if (in != creases || nearest_other <= outer)
        return;
      const double score = std::min(nearest_other - outer, 0.6 * inner - farthest_in);
      if (!best || score > best_score) {
        best_score = score;
        best = CreaseTarget{{"creases_" + std::to_string(creases), v, 0.0}, radius_rel};
      }
    };
    if (creases == 3) {
      for (const auto& corner : model.features.corners) {
        if (options.concave_corner && corner.signature().find('r') == std::string::npos)
          continue;
        int incident = 0;
        for (const auto& chain : chains) {
          incident += (!chain.closed && (chain.vertices.front() == corner.vertex ||
                                         chain.vertices.back() == corner.vertex))
                          ? 1
                          : 0;
        }
        if (incident == 3)
          consider(corner.vertex);
      }
    } else {
      for (auto v : mesh.vertices())
        consider(v);
    }
    if (best)
      return best;
  }
  return std::nullopt;
}

Case make_crease_hole_case(const AnalysedModel& model, int creases, const std::string& id,
                           const CreaseHoleOptions& options) {
  const auto target = find_crease_target(model, creases, options);
  if (!target) {
    throw std::invalid_argument("model '" + model.name + "' has no place where a hole crosses " +
                                std::to_string(creases) + " creases" +
                                (options.concave_corner ? " at a concave corner" : ""));
  }
  PunchedCaseOptions punch;
  punch.radius_rel_diag = target->radius_rel_diag;
  punch.irregularity = options.irregularity;
  punch.structure_size_rel_diag = options.structure_size_rel_diag;
  punch.shape_seed = stable_hash(id);
  Case c = make_punched_case(model, target->target, punch);
  c.id = id;
  c.family = "crease";
  return c;
}

}  // namespace holebench::generators
