#include "core/labels_summary.h"

#include <gtest/gtest.h>

namespace holebench {
namespace {

// The one-line labels of `holebench cases list --labels`, on hand-made labels: numbers with
// 3 significant digits, transitions in loop order, holes without labels named by target.
TEST(LabelsSummary, OneLineForTheHolesOfACase) {
  Case c;
  HoleTruth corner;
  corner.target = "corner";
  HoleLabels l;
  l.k = 3;
  l.transitions = {Convexity::Convex, Convexity::Convex, Convexity::Reflex};
  l.size = 0.05;
  l.structure_size = 0.0612345;
  corner.labels = l;
  HoleTruth outer;
  outer.target = "edge";
  HoleLabels o;
  o.k = 2;
  o.orientation = Orientation::Outer;
  o.transitions = {Convexity::Reflex};
  o.boundary_kinds = {BoundaryKind::Inner, BoundaryKind::Outer};
  o.linearly_dependent_faces = true;
  o.size = 1.0;
  o.structure_size = 0.5;
  o.expected_decision = Decision::Guide;
  o.known_weak_spot = "twisted_face";
  outer.labels = o;
  HoleTruth unlabelled;
  unlabelled.target = "face_interior";
  c.holes = {corner, outer, unlabelled};
  EXPECT_EQ(labels_summary(c),
            "k=3 inner [convex,convex,reflex] size 0.05 vs 0.0612: close; "
            "k=2 outer [reflex] boundary inner,outer parallel faces size 1 vs 0.5: guide "
            "(weak spot: twisted_face); face_interior (no labels)");
  EXPECT_EQ(labels_summary(Case{}), "");
}

}  // namespace
}  // namespace holebench
