// The mean search of surface_distance.h, in mean_search.cpp: directed_mean_distance() by
// branch and bound on the cells of A (the bounds of each cell as surface_distance.h describes
// them), the first-pass tables MeanCellBounds and the recorded steps MeanSearchSteps; and what
// surface_distance() takes from those tables for its first pass over the vertices.
#pragma once

#include "core/mesh.h"
#include "metrics/surface_distance.h"
#include "metrics/vertex_distances.h"

namespace holebench {

/// The first pass's answers that `first` holds for its A0's vertices (MeanCellBounds), for
/// the vertices of A: a vertex of A at the index of an A0 vertex, with its point bit for
/// bit, that A0's pass queried has A0's answer against B0. That is its answer against B too
/// where B's and B0's faces within the answer's distance are the same triangles in the same
/// order (SurfaceChange): the ball about the point (padded far above rounding) misses the
/// changed box, and the nearest face of B0 is a face of B. None without `first`.
EarlierVertexAnswer earlier_vertex_answers(const Mesh& a, const FirstBounds* first);

}  // namespace holebench
