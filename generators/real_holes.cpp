#include "generators/real_holes.h"

#include "core/boundary_loops.h"
#include "core/errors.h"
#include "core/face_rings.h"
#include "core/geometry.h"
#include "generators/hole_punch.h"

#include <algorithm>
#include <stdexcept>

namespace holebench::generators {
namespace {

// Per face: the index of its connected component (faces joined across edges).
std::vector<int> face_components(const Mesh& mesh, int& count) {
  std::vector<int> component(mesh.n_faces(), -1);
  count = 0;
  for (auto start : mesh.faces()) {
    if (component[start.idx()] >= 0)
      continue;
    std::vector<FaceHandle> stack{start};
    component[start.idx()] = count;
    while (!stack.empty()) {
      const FaceHandle f = stack.back();
      stack.pop_back();
      for (auto neighbour : mesh.ff_range(f)) {
        if (component[neighbour.idx()] < 0) {
          component[neighbour.idx()] = count;
          stack.push_back(neighbour);
        }
      }
    }
    ++count;
  }
  return component;
}

double vector_area(const std::vector<Point>& loop) {
  Point sum(0.0, 0.0, 0.0);
  for (std::size_t i = 0; i < loop.size(); ++i)
    sum += loop[i] % loop[(i + 1) % loop.size()];  // OpenMesh: % is the cross product
  return 0.5 * sum.norm();
}

Case real_hole_case_shell(const Mesh& mesh, const std::string& id) {
  Case c;
  c.id = id;
  c.family = "file";
  c.complete = mesh;
  mark_all_original(c.complete);
  return c;
}

}  // namespace

const std::vector<int>& ring_removal_counts() {
  static const std::vector<int> counts{1, 2, 4};
  return counts;
}

const BoundaryLoop& hole_loop(const MeshLoops& loops, int hole) {
  if (hole < 0 || hole >= static_cast<int>(loops.holes.size())) {
    throw std::invalid_argument("the mesh has " + std::to_string(loops.holes.size()) +
                                " holes; there is no hole " + std::to_string(hole));
  }
  return loops.loops[static_cast<std::size_t>(loops.holes[static_cast<std::size_t>(hole)])];
}

MeshLoops classify_boundary_loops(const Mesh& mesh) {
  int component_count = 0;
  const std::vector<int> component = face_components(mesh, component_count);
  std::vector<double> component_area(static_cast<std::size_t>(component_count), 0.0);
  for (auto f : mesh.faces())
    component_area[static_cast<std::size_t>(component[f.idx()])] += face_area(mesh, f);
  MeshLoops sorted;
  sorted.loops = find_boundary_loops(mesh);
  const std::vector<BoundaryLoop>& loops = sorted.loops;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    const FaceHandle face = mesh.face_handle(mesh.opposite_halfedge_handle(loops[i].halfedges[0]));
    const double area = component_area[static_cast<std::size_t>(component[face.idx()])];
    const bool border = vector_area(loop_points(mesh, loops[i])) >= 0.5 * area;
    (border ? sorted.sheet_borders : sorted.holes).push_back(static_cast<int>(i));
  }
  return sorted;
}

std::vector<int> faces_around_loop(const Mesh& mesh, const BoundaryLoop& loop, int rings) {
  const std::vector<char> chosen = faces_within_rings(mesh, loop_vertices(mesh, loop), rings);
  std::vector<int> faces;
  for (std::size_t f = 0; f < chosen.size(); ++f) {
    if (chosen[f])
      faces.push_back(static_cast<int>(f));
  }
  return faces;
}

Case make_real_hole_case(const Mesh& mesh, int hole, const std::string& id) {
  hole_loop(classify_boundary_loops(mesh), hole);  // throws where there is no such hole
  Case c = real_hole_case_shell(mesh, id);
  c.kind = "real_hole";
  c.has_ground_truth = false;
  c.input = c.complete;
  HoleTruth truth;
  truth.target = "real_hole";
  truth.unlabelled_because = "a real hole: no ground truth";
  c.holes.push_back(std::move(truth));
  return c;
}

Case make_ring_removal_case(const Mesh& mesh, int hole, int rings, const std::string& id) {
  const MeshLoops loops = classify_boundary_loops(mesh);
  const BoundaryLoop& loop = hole_loop(loops, hole);
  Case c = real_hole_case_shell(mesh, id);
  c.kind = "rings-" + std::to_string(rings);
  c.truth_surrounds_a_real_hole = true;
  PunchResult punched = punch_faces(c.complete, faces_around_loop(c.complete, loop, rings));
  if (punched.holed.n_faces() == 0)
    throw InvalidInputError(id + ": removing " + std::to_string(rings) +
                            " rings around the hole leaves no face");
  c.input = std::move(punched.holed);
  HoleTruth truth;
  truth.target = c.kind;
  truth.removed_faces = std::move(punched.removed_faces);
  truth.unlabelled_because = "a real hole enlarged by its rings: no taxonomy labels";
  c.holes.push_back(std::move(truth));
  return c;
}

}  // namespace holebench::generators
