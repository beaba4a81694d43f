#include "harness/oracle_user.h"

#include "core/geometry.h"

#include <limits>
#include <stdexcept>

namespace holebench::harness {

int nearest_truth_hole(const Case& c, const Point& point) {
  int best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < c.holes.size(); ++i) {
    for (int f : c.holes[i].removed_faces) {
      const double d = (face_centroid(c.complete, c.complete.face_handle(f)) - point).norm();
      if (d < best_distance) {
        best_distance = d;
        best = static_cast<int>(i);
      }
    }
  }
  return best;
}

bool OracleUser::agree_to_closing(const ClosingProposal& proposal) {
  const int hole = nearest_truth_hole(case_, proposal.hole_centroid);
  if (hole < 0 || !case_.holes[hole].labels)
    return true;
  const bool agree = case_.holes[hole].labels->expected_decision == Decision::CloseAutomatically;
  if (!agree)
    count_intervention();
  return agree;
}

void check_user_kind(const std::string& kind) {
  if (kind != "no_user" && kind != "oracle") {
    throw std::invalid_argument("unknown user '" + kind + "' (no_user or oracle)");
  }
}

std::unique_ptr<User> make_user(const std::string& kind, const Case& c) {
  check_user_kind(kind);
  if (kind == "oracle")
    return std::make_unique<OracleUser>(c);
  return std::make_unique<NoUser>();
}

}  // namespace holebench::harness
