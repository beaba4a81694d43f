#include "methods/brep_guidance/exact_closing.h"

#include "methods/brep_guidance/closing_plan.h"
#include "methods/brep_guidance/closing_triangulation.h"
#include "methods/common/patch_intersections.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace holebench::brep_guidance {
namespace {

// The planned faces' triangles added to the mesh, each with the region of the face it
// extends. A part split at the loop's vertices, triangulated in the loop's order or turned
// over in its plane need not be embedded: the closing is kept only if it intersects neither
// itself nor the mesh around it. On failure the mesh is left as it was.
void apply_closing(Mesh& mesh, const ClosingPlan& plan, const ClosingTriangles& triangles,
                   ClosingResult& result) {
  const Mesh backup = mesh;
  std::vector<VertexHandle> new_vertices;
  std::vector<FaceHandle> added_faces;
  for (const Point& p : plan.new_points)
    new_vertices.push_back(mesh.add_vertex(p));
  auto handle = [&](const PolygonCorner& c) {
    return c.vertex.is_valid() ? c.vertex : new_vertices[c.new_index];
  };
  for (std::size_t f = 0; f < plan.faces.size(); ++f) {
    for (const auto& t : triangles.triangles[f]) {
      const FaceHandle added = mesh.add_face(handle(t[0]), handle(t[1]), handle(t[2]));
      if (!added.is_valid()) {
        mesh = backup;
        result.error = "a closing triangle would make the mesh non-manifold";
        return;
      }
      set_region(mesh, added, plan.faces[f].region);
      added_faces.push_back(added);
      ++result.new_faces;
    }
  }
  if (const std::size_t pairs = patch_intersections(mesh, added_faces); pairs > 0) {
    mesh = backup;
    result.error = "the closing would intersect itself or the mesh around it (" +
                   std::to_string(pairs) + " face pairs)";
    result.new_faces = 0;
    return;
  }
  result.new_vertices = plan.new_points.size();
  result.closed = true;
}

// One attempt: the faces' polygons planned (closing_plan.h), triangulated
// (closing_triangulation.h), then added to the mesh and checked. `applicable`: false where the
// attempt does not apply to the hole.
ClosingResult close_hole(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                         const ClosingAttempt& attempt, bool* applicable = nullptr) {
  if (applicable != nullptr)
    *applicable = true;
  ClosingResult result;
  const int k = hole.k();
  if (k > 3 || (k == 3 && !hole.S) || (k == 2 && hole.linearly_dependent)) {
    result.error = "only inner holes with k <= 3 and independent planes are closed";
    return result;
  }
  const ClosingPlan plan = plan_closing(mesh, faces, hole, attempt);
  if (!plan.applicable) {
    if (applicable != nullptr)
      *applicable = false;
    result.error = "not applicable";
    return result;
  }
  result.note = plan.note;
  const ClosingTriangles triangles = triangulate_closing(mesh, faces, plan, attempt);
  for (const std::string& note : triangles.notes) {
    if (!result.note.empty())
      result.note += "; ";
    result.note += note;
  }
  if (!triangles.ok) {
    result.error = triangles.error;
    return result;
  }
  apply_closing(mesh, plan, triangles, result);
  return result;
}

}  // namespace

ClosingResult close_hole_exactly(Mesh& mesh, const BrepFaces& faces, const Hole& hole,
                                 bool later_attempts) {
  // First as planned; then with the loop's vertices on the rebuilt edges as its corners (the
  // loop touches the faces' common line between the edge's ends); then with parts whose
  // projection is not simple triangulated in the loop's order; then with such parts first
  // triangulated in their own least-squares planes; then (k = 3) with a face whose part is at
  // most one loop edge given to a neighbour and the hole closed as k = 2 without S; then
  // (k >= 2) the loop as one part in its own plane, where it lies in one within its faces'
  // noise. The first that closes counts; the error is the first attempt's, followed by the
  // last error of each later kind that applied.
  ClosingResult first = close_hole(mesh, faces, hole, ClosingAttempt{});
  if (first.closed || !later_attempts)
    return first;
  struct Try {
    ClosingAttempt attempt;
    const char* note;
    const char* error_label;  // the failure reported after the first attempt's, if any
  };
  const char* on_edges = "loop vertices on the rebuilt edges used as its corners";
  std::vector<Try> tries{
      {ClosingAttempt{true, false, false}, on_edges, nullptr},
      {ClosingAttempt{true, true, false}, on_edges,
       "split at the loop's vertices and in the loop's order"},
      {ClosingAttempt{false, true, false}, "", nullptr},
      {ClosingAttempt{false, true, true}, "", nullptr},
      {ClosingAttempt{true, true, true}, on_edges, "in the parts' own planes"},
  };
  if (hole.k() == 3) {
    for (int j = 0; j < 3; ++j) {
      for (bool into_previous : {true, false}) {
        for (bool vertices_on_edges : {false, true}) {
          tries.push_back({ClosingAttempt{vertices_on_edges, true, true, j, into_previous},
                           vertices_on_edges ? on_edges : "",
                           "with a face's run of at most one edge given to a neighbour (k = 2)"});
        }
      }
    }
  }
  if (hole.k() >= 2) {
    ClosingAttempt one_plane{false, true, true};
    one_plane.one_plane = true;
    tries.push_back({one_plane, "", "as one part in the loop's plane"});
  }
  std::vector<std::pair<std::string, std::string>> errors;  // by label, the last of each
  for (const Try& t : tries) {
    if (t.attempt.loop_vertices_on_edges && hole.k() < 2)
      continue;
    bool applicable = true;
    ClosingResult result = close_hole(mesh, faces, hole, t.attempt, &applicable);
    if (!applicable)
      continue;
    if (!result.closed) {
      if (t.error_label != nullptr) {
        const auto same = std::find_if(errors.begin(), errors.end(),
                                       [&](const auto& e) { return e.first == t.error_label; });
        if (same != errors.end())
          same->second = result.error;
        else
          errors.push_back({t.error_label, result.error});
      }
      continue;
    }
    std::string note = t.note;
    if (!result.note.empty())
      note += (note.empty() ? "" : "; ") + result.note;
    result.note = note;
    return result;
  }
  for (const auto& [label, error] : errors)
    first.error += "; " + label + ": " + error;
  return first;
}

}  // namespace holebench::brep_guidance
