#include "metrics/appended_repair_starts.h"

#include "metrics/embree/triangle_scene.h"
#include "metrics/triangle_cell.h"
#include "metrics/triangle_geometry.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <atomic>
#include <cstddef>

namespace holebench {
namespace {

constexpr double kUnknown = kUnknownVertexDistance;

// A face's area as the mean search takes it: of its cell's corners (triangle_cell.h).
double cell_area(const Mesh& mesh, FaceHandle f, const VertexDistances& vertices) {
  return triangle_area(face_cell(mesh, f, vertices).corners);
}

// The faces of `repaired` after the input's, deleted ones left out, in index order.
std::vector<int> appended_faces(const Mesh& repaired, std::size_t input_faces) {
  std::vector<int> faces;
  for (std::size_t f = input_faces; f < repaired.n_faces(); ++f) {
    if (!repaired.status(FaceHandle(static_cast<int>(f))).deleted())
      faces.push_back(static_cast<int>(f));
  }
  return faces;
}

// Whether `kept` says the repair appends to an input of `input_faces` faces and
// `input_vertices` vertices.
bool appends(const Mesh& repaired, const KeptFaces& kept, std::size_t input_faces,
             std::size_t input_vertices) {
  return kept.appends_to_input() && repaired.n_faces() >= input_faces &&
         repaired.n_vertices() >= input_vertices;
}

}  // namespace

AppendedRepairStarts::AppendedRepairStarts(const Mesh& input, const Mesh& complete,
                                           const FirstPass& input_pass,
                                           const SharedFaces& input_shared)
    : input_faces_(input.n_faces()),
      input_vertices_(input.n_vertices()),
      input_pass_(input_pass.vertices) {
  // As the searches pass over the input's faces (in index order, the area of those with
  // area summed in that order).
  for (auto f : input.faces()) {
    const double area = cell_area(input, f, input_pass_);
    if (area > 0.0)
      input_area_ += area;
    if (input_pass.b_face_of_a[f.idx()] < 0)
      input_unshared_faces_.push_back(f.idx());
  }
  // As vertex_distances() marks the complete model's vertices on faces it shares with the
  // input (in face order: a later face's mark stands), and the faces it searches.
  complete_marked_.distance.assign(complete.n_vertices(), kUnknown);
  complete_marked_.nearest_face.assign(complete.n_vertices(), -1);
  for (auto g : complete.faces()) {
    const int match = input_shared.a_face_of_b[g.idx()];
    if (match >= 0)
      mark_vertices_on_shared_face(complete, g, match, complete_marked_);
    else
      complete_unshared_faces_.push_back(g.idx());
  }
  for (std::size_t v = 0; v < complete.n_vertices(); ++v) {
    if (complete_marked_.distance[v] == kUnknown)
      complete_unmarked_vertices_.push_back(static_cast<int>(v));
  }
  // The complete model's area with the same cells' corners (distances do not enter it).
  for (auto g : complete.faces()) {
    const double area = cell_area(complete, g, complete_marked_);
    if (area > 0.0)
      complete_area_ += area;
  }
}

std::optional<SearchStart> AppendedRepairStarts::repaired_to_complete(
    const Mesh& repaired, const KeptFaces& kept, const SharedFaces& repaired_shared,
    const embree::TriangleScene& complete_scene) const {
  if (!appends(repaired, kept, input_faces_, input_vertices_))
    return std::nullopt;
  SearchStart start;
  // The input's vertices answer as in the input's first pass (the same points against the
  // same surface); a new face on the complete model marks its vertices, after the input's
  // faces as in face order; the new vertices left are queried.
  start.vertices.distance = input_pass_.distance;
  start.vertices.nearest_face = input_pass_.nearest_face;
  start.vertices.distance.resize(repaired.n_vertices(), kUnknown);
  start.vertices.nearest_face.resize(repaired.n_vertices(), -1);
  const std::vector<int> added = appended_faces(repaired, input_faces_);
  for (int f : added) {
    const int match = repaired_shared.b_face_of_a[f];
    if (match >= 0)
      mark_vertices_on_shared_face(repaired, FaceHandle(f), match, start.vertices);
  }
  for (std::size_t v = input_vertices_; v < repaired.n_vertices(); ++v) {
    if (start.vertices.distance[v] != kUnknown)
      continue;
    const auto closest =
        complete_scene.closest_point(repaired.point(VertexHandle(static_cast<int>(v))));
    start.vertices.distance[v] = closest.distance;
    start.vertices.nearest_face[v] = closest.face;
    ++start.vertices.queries;
  }
  // The input's faces not on the complete model, then the new ones; the area likewise.
  start.unshared_faces = input_unshared_faces_;
  start.area = input_area_;
  for (int f : added) {
    const double area = cell_area(repaired, FaceHandle(f), start.vertices);
    if (area > 0.0)
      start.area += area;
    if (repaired_shared.b_face_of_a[f] < 0)
      start.unshared_faces.push_back(f);
  }
  return start;
}

std::optional<SearchStart> AppendedRepairStarts::complete_to_repaired(
    const Mesh& complete, const Mesh& repaired, const KeptFaces& kept,
    const SharedFaces& repaired_shared, const embree::TriangleScene& repaired_scene,
    const EarlierVertexAnswer& earlier) const {
  if (!appends(repaired, kept, input_faces_, input_vertices_))
    return std::nullopt;
  SearchStart start;
  start.vertices = complete_marked_;
  // The complete model's faces that a new face matches (none of them matched an input face)
  // mark their vertices too: each such vertex takes the mark of its last shared face in
  // face order, as vertex_distances() leaves it.
  const std::vector<int> added = appended_faces(repaired, input_faces_);
  for (int f : added) {
    const int g = repaired_shared.b_face_of_a[f];
    if (g < 0)
      continue;
    for (auto v : complete.fv_range(FaceHandle(g))) {
      int last = -1;
      for (auto h : complete.vf_range(v)) {
        if (repaired_shared.a_face_of_b[h.idx()] >= 0)
          last = std::max(last, h.idx());
      }
      start.vertices.distance[v.idx()] = 0.0;
      start.vertices.nearest_face[v.idx()] = repaired_shared.a_face_of_b[last];
    }
  }
  // The vertices left: the answer against the input where it holds for the repair
  // (`earlier`), else a query; each answer is the same whatever the order.
  std::atomic<std::size_t> queries{0};
  const auto& unmarked = complete_unmarked_vertices_;
  tbb::parallel_for(
      tbb::blocked_range<std::size_t>(0, unmarked.size(), 1024), [&](const auto& range) {
        std::size_t count = 0;
        for (std::size_t i = range.begin(); i != range.end(); ++i) {
          const int v = unmarked[i];
          double& distance = start.vertices.distance[v];
          int& face = start.vertices.nearest_face[v];
          if (distance != kUnknown || (earlier && earlier(v, distance, face)))
            continue;
          const auto closest = repaired_scene.closest_point(complete.point(VertexHandle(v)));
          distance = closest.distance;
          face = closest.face;
          ++count;
        }
        queries += count;
      });
  start.vertices.queries = queries;
  for (int g : complete_unshared_faces_) {
    if (repaired_shared.a_face_of_b[g] < 0)
      start.unshared_faces.push_back(g);
  }
  start.area = complete_area_;
  return start;
}

}  // namespace holebench
