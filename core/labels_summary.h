// A case's labels as one line of text, for people: `holebench cases list --labels` and the
// captions of the case gallery.
#pragma once

#include "core/case.h"

#include <string>

namespace holebench {

/// One line with the labels of a case's holes, "; " between holes, e.g. "k=3 inner
/// [convex,convex,reflex] size 0.05 vs 0.06: close" (then, where they apply, " boundary
/// inner,outer", " parallel faces", " (weak spot: ...)"); a hole without labels is
/// "<target> (no labels)".
std::string labels_summary(const Case& c);

/// The label combination of one hole, as the B-Rep cases and the face-removal cases are
/// grouped by: "k<k>/<orientation>[/<convexities>][/<kinds>]", with the convexities and
/// boundary kinds as sorted multisets joined by '-'; for k = 2 a single word when both
/// transitions agree (docs/cases.md).
std::string combo_of(const HoleLabels& labels);

}  // namespace holebench
