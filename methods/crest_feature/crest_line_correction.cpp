#include "methods/crest_feature/crest_line_correction.h"

#include <cmath>

namespace holebench::crest_feature {
namespace {

bool finite(const Point& p) {
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

CrestLineProposal make_proposal(const Mesh& mesh, const Hole& hole, int hole_index,
                                const HoleFeatures& features) {
  CrestLineProposal proposal;
  proposal.hole_index = hole_index;
  proposal.hole_centroid = hole.centroid;
  for (auto v : hole.vertices)
    proposal.boundary.push_back(mesh.point(v));
  for (const auto& f : features.points) {
    proposal.feature_points.push_back(f.position);
    proposal.directions.push_back(f.tangent);
  }
  return proposal;
}

}  // namespace

CrestLineCorrection review_crest_lines(const Mesh& mesh, const Hole& hole, int hole_index,
                                       const HoleFeatures& features, User& user) {
  CrestLineCorrection result{features, 0};
  if (features.points.empty())
    return result;
  const CrestLineProposal answer =
      user.review_crest_lines(make_proposal(mesh, hole, hole_index, features));
  if (answer.directions.size() != features.points.size())
    return result;
  for (std::size_t i = 0; i < features.points.size(); ++i) {
    Point d = answer.directions[i];
    const double n = d.norm();
    if (!finite(d) || !(n > 0.0))
      continue;
    d /= n;
    FeaturePoint& f = result.features.points[i];
    if ((d - f.tangent).norm() <= 1e-12)
      continue;  // unchanged
    f.tangent = d;
    f.crest_line = -1;
    ++result.corrected;
  }
  return result;
}

}  // namespace holebench::crest_feature
