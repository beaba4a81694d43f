// Sharp creases as crest lines (not in the crest-line paper; the project's own reading of
// section 3.2 on CAD meshes). A CAD mesh's crease is a line of mesh edges across which the
// normal turns at once. The jet fit of crest_lines.h is a smooth polynomial over 2-4 rings,
// which spreads that turn over the crease's neighbours, so the fitted ridges run beside the
// crease and drift off it near a hole (up to 45 degrees on cad/joint/edge_convex). Where the
// mesh has such a crease, its crest line is taken to be the crease itself: the chain of edges
// whose dihedral angle exceeds a threshold (a ridge where convex, a ravine where reflex, as
// equations 1 and 2 classify them), and the jet-fitted crest points beside it are dropped.
// See docs/crest_feature.md ("Sharp creases").
#pragma once

#include "core/mesh.h"
#include "methods/crest_feature/crest_lines.h"

#include <vector>

namespace holebench::crest_feature {

/// The sharp creases of `mesh` among the edges whose two vertices are in `in_band` (per
/// vertex index): chains of edges whose unsigned dihedral angle exceeds
/// `options.sharp_crease_angle_degrees`, each ending where the crease ends, meets another
/// (a corner), reaches a boundary vertex, changes convexity or turns by more than
/// `options.sharp_crease_bend_degrees` at a vertex. Crest points are the chain's vertices;
/// `mean_curvature` is the mean dihedral angle over `mean_edge_length` (the normal's turn
/// spread over one edge). An end at a corner or a bend is not a run-out end
/// (CrestLine::runs_out): the crease does not continue straight there. Chains with at most
/// `options.min_segments` points are left out, as jet-fitted lines are, unless they reach a
/// boundary vertex (a crease between a hole and a corner near it is short).
std::vector<CrestLine> trace_sharp_creases(const Mesh& mesh, const std::vector<char>& in_band,
                                           double mean_edge_length,
                                           const CrestLineOptions& options);

/// Drops the crest points of `lines` that lie within `clearance` of a point of `creases`'
/// polylines; each line is cut into its runs of kept points, and runs with at most
/// `min_segments` points are left out.
void drop_crest_points_near(std::vector<CrestLine>& lines, const std::vector<CrestLine>& creases,
                            double clearance, int min_segments);

}  // namespace holebench::crest_feature
