#include "methods/external/output_patch.h"

#include "core/boundary_loops.h"
#include "core/errors.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace holebench {

namespace {

using Position = std::array<double, 3>;
using FaceKey = std::array<int, 3>;

Position position(const Point& p) {
  return {p[0], p[1], p[2]};
}

// The face's corners (input vertex indices) rotated so that the smallest comes first: the
// same key for the same face whatever corner it starts at; a flipped face gets another key.
FaceKey face_key(int a, int b, int c) {
  FaceKey key{a, b, c};
  const auto smallest = std::min_element(key.begin(), key.end()) - key.begin();
  std::rotate(key.begin(), key.begin() + smallest, key.end());
  return key;
}

// The input vertex an output position stands for: the first input vertex at exactly that
// position or, with a tolerance, the nearest one within it (a grid of cells of that size).
class InputVertexLookup {
 public:
  InputVertexLookup(const Mesh& holed, double tolerance) : mesh_(holed), tolerance_(tolerance) {
    for (auto v : holed.vertices()) {
      exact_.emplace(position(holed.point(v)), v);
      if (tolerance_ > 0.0)
        grid_[cell(holed.point(v))].push_back(v);
    }
  }

  /// The input vertex, or an invalid handle.
  VertexHandle find(const Point& p) const {
    if (const auto it = exact_.find(position(p)); it != exact_.end())
      return it->second;
    if (tolerance_ <= 0.0)
      return VertexHandle();
    const Cell c = cell(p);
    VertexHandle best;
    double best_distance = tolerance_;
    for (long dx = -1; dx <= 1; ++dx) {
      for (long dy = -1; dy <= 1; ++dy) {
        for (long dz = -1; dz <= 1; ++dz) {
          const auto it = grid_.find({c[0] + dx, c[1] + dy, c[2] + dz});
          if (it == grid_.end())
            continue;
          for (auto v : it->second) {
            const double distance = (mesh_.point(v) - p).norm();
            if (distance <= best_distance)
              best = v, best_distance = distance;
          }
        }
      }
    }
    return best;
  }

  /// The vertex standing for input vertex `v` (the first one at its position).
  VertexHandle representative(VertexHandle v) const { return exact_.at(position(mesh_.point(v))); }

 private:
  using Cell = std::array<long, 3>;
  Cell cell(const Point& p) const {
    return {static_cast<long>(std::floor(p[0] / tolerance_)),
            static_cast<long>(std::floor(p[1] / tolerance_)),
            static_cast<long>(std::floor(p[2] / tolerance_))};
  }

  const Mesh& mesh_;
  double tolerance_;
  std::map<Position, VertexHandle> exact_;
  std::map<Cell, std::vector<VertexHandle>> grid_;
};

// The patch's faces reached from `start` across edges between new faces, and their vertices.
void collect_patch_part(const Mesh& mesh, FaceHandle start, std::set<int>& seen,
                        HoleReport& report) {
  std::vector<FaceHandle> stack{start};
  seen.insert(start.idx());
  std::set<int> vertices;
  while (!stack.empty()) {
    const FaceHandle f = stack.back();
    stack.pop_back();
    ++report.new_faces;
    for (auto v : mesh.fv_range(f)) {
      if (is_new(mesh, v))
        vertices.insert(v.idx());
    }
    for (auto g : mesh.ff_range(f)) {
      if (is_new(mesh, g) && seen.insert(g.idx()).second)
        stack.push_back(g);
    }
  }
  report.new_vertices += vertices.size();
}

std::vector<HoleReport> hole_reports(const Mesh& holed, const Mesh& repaired) {
  std::vector<HoleReport> reports;
  std::set<int> seen;
  const auto loops = find_boundary_loops(holed);
  for (std::size_t i = 0; i < loops.size(); ++i) {
    HoleReport report;
    report.hole_index = static_cast<int>(i);
    report.loop_size = loops[i].size();
    report.centroid = loop_centroid(holed, loops[i]);
    report.closed = true;
    for (auto h : loops[i].halfedges) {
      // The repaired mesh keeps the input's handles: the loop's half-edge has a face now if
      // the patch covers it.
      const FaceHandle f = repaired.face_handle(h);
      report.closed = report.closed && f.is_valid();
      if (f.is_valid() && is_new(repaired, f) && !seen.count(f.idx()))
        collect_patch_part(repaired, f, seen, report);
    }
    if (!report.closed)
      report.note = "the program's output leaves (part of) the hole open";
    reports.push_back(std::move(report));
  }
  return reports;
}

}  // namespace

OutputPatch recover_output_patch(const Mesh& holed, const TriangleSoup& output,
                                 double vertex_tolerance) {
  for (const auto& p : output.points) {
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
      throw InvalidInputError("a vertex with a non-finite coordinate");
  }
  const int points = static_cast<int>(output.points.size());
  for (const auto& t : output.triangles) {
    for (int index : t) {
      if (index < 0 || index >= points)
        throw InvalidInputError("a face with vertex index " + std::to_string(index) + " of " +
                                std::to_string(points));
    }
  }
  OutputPatch patch;
  patch.repaired = holed;
  Mesh& mesh = patch.repaired;
  const InputVertexLookup lookup(holed, vertex_tolerance);

  std::map<FaceKey, int> input_faces;  // key -> how many input faces have it
  for (auto f : holed.faces()) {
    std::vector<int> corners;
    for (auto v : holed.fv_range(f))
      corners.push_back(lookup.representative(v).idx());
    ++input_faces[face_key(corners[0], corners[1], corners[2])];
  }
  // Output vertices: the input vertex they stand for, else a new vertex (made when a patch
  // face first uses it).
  std::vector<VertexHandle> vertex_of(output.points.size());
  for (std::size_t i = 0; i < output.points.size(); ++i)
    vertex_of[i] = lookup.find(output.points[i]);
  std::vector<std::array<int, 3>> patch_faces;
  for (const auto& t : output.triangles) {
    const VertexHandle a = vertex_of[t[0]], b = vertex_of[t[1]], c = vertex_of[t[2]];
    const auto it = a.is_valid() && b.is_valid() && c.is_valid()
                        ? input_faces.find(face_key(a.idx(), b.idx(), c.idx()))
                        : input_faces.end();
    if (it != input_faces.end() && it->second > 0) {
      --it->second;
    } else {
      patch_faces.push_back(t);
    }
  }
  for (const auto& [key, left] : input_faces)
    patch.input_faces_missing += static_cast<std::size_t>(left);

  for (const auto& t : patch_faces) {
    std::array<VertexHandle, 3> corners;
    for (int k = 0; k < 3; ++k) {
      VertexHandle& v = vertex_of[t[k]];
      if (!v.is_valid())
        v = mesh.add_vertex(output.points[t[k]]);
      corners[k] = v;
    }
    const bool distinct =
        corners[0] != corners[1] && corners[1] != corners[2] && corners[0] != corners[2];
    const FaceHandle f =
        distinct ? mesh.add_face(corners[0], corners[1], corners[2]) : FaceHandle();
    if (f.is_valid())
      ++patch.new_faces;
    else
      ++patch.refused_faces;
  }
  patch.holes = hole_reports(holed, mesh);
  return patch;
}

MethodResult result_of_output_patch(OutputPatch patch) {
  MethodResult result;
  result.repaired = std::move(patch.repaired);
  result.holes = std::move(patch.holes);
  std::size_t open = 0;
  for (const auto& hole : result.holes)
    open += hole.closed ? 0 : 1;
  result.status = open == 0                                             ? MethodStatus::Ok
                  : open == result.holes.size() && patch.new_faces == 0 ? MethodStatus::Failed
                                                                        : MethodStatus::Partial;
  if (open > 0) {
    result.message =
        std::to_string(open) + " of " + std::to_string(result.holes.size()) + " holes left open";
  }
  if (patch.refused_faces > 0) {
    result.message += (result.message.empty() ? "" : "; ") + std::to_string(patch.refused_faces) +
                      " of the program's new faces left out (degenerate, or non-manifold with "
                      "the rest)";
  }
  return result;
}

}  // namespace holebench
