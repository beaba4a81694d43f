// The human in the loop. Where a paper asks a person (agree to an automatic closing,
// pair feature points), a method asks this interface; the harness answers from the
// ground truth (an oracle user) or not at all (no user), and counts the interventions.
#pragma once

#include "core/mesh.h"

#include <string>

namespace holebench {

/// What a method proposes for one hole before closing it automatically.
struct ClosingProposal {
  int hole_index = 0;   ///< index of the hole in the method's detection order
  Point hole_centroid;  ///< where the hole is, so that an oracle can find its ground truth
  double hole_size = 0.0;
};

class User {
 public:
  virtual ~User() = default;

  /// "no_user" or "oracle": written into every record.
  virtual std::string kind() const = 0;

  /// The B-Rep paper's cases a and b: may the hole be closed automatically?
  virtual bool agree_to_closing(const ClosingProposal& proposal) = 0;

  /// How many times this user changed what the method would have done alone.
  int interventions() const { return interventions_; }

 protected:
  void count_intervention() { ++interventions_; }

 private:
  int interventions_ = 0;
};

/// No human: agrees to everything, never intervenes.
class NoUser final : public User {
 public:
  std::string kind() const override { return "no_user"; }
  bool agree_to_closing(const ClosingProposal&) override { return true; }
};

}  // namespace holebench
