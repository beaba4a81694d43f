// Views and overlays of a case: where to look at its hole, and the figure-5 style marks of
// the B-Rep paper (hole boundary, transition vertices, face normals).
#pragma once

#include "core/case.h"
#include "core/method_result.h"
#include "harness/outputs/render/snapshot.h"

namespace holebench::render {

/// The view of a case: along the area-weighted mean normal of the removed faces of the
/// complete model, tilted a little so that edges and depth read. It uses the ground truth,
/// which the harness may; it is the same for every method of a case, so pictures compare.
Camera hole_camera(const Case& c);

/// Marks on a holed mesh: its boundary loops (red), the transition vertices where a loop
/// passes from one region to the next (dark dots), and one normal per region next to a
/// hole (black strokes), as figure 5 of the B-Rep paper shows its cases.
Overlay hole_overlay(const Mesh& holed, double normal_length);

/// A guidance arrow (the B-Rep paper's (P, r)) drawn as a shaded 3D arrow: a round shaft
/// from P along r of `length` with a cone at its tip (render/snapshot.h's arrow_solid), and
/// P marked by a dot.
void add_arrow(Overlay& overlay, const GuidanceArrow& arrow, double length);
/// Every hole's guidance arrow in `result`, its shaft pointing from P most of the way to the
/// hole (at least 5 % of the complete model's diagonal long).
void add_guidance_arrows(Overlay& overlay, const Case& c, const MethodResult& result);

/// The snapshot of a job: the repaired mesh from the case's hole view, with every guidance
/// arrow of the method drawn in.
Image job_snapshot(const Case& c, const MethodResult& result, const SnapshotOptions& options = {});

}  // namespace holebench::render
