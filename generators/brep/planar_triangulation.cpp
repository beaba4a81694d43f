#include "generators/brep/planar_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <list>
#include <stdexcept>

namespace holebench::generators::brep {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
struct FaceInfo {
  int nesting_level = -1;
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase =
    CGAL::Triangulation_face_base_with_info_2<FaceInfo, Kernel,
                                              CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// Floods the faces reachable from `start` without crossing a constraint with `level`;
// the faces across constraints are queued for the next level (CGAL's polygon example).
void mark_domains(Cdt& cdt) {
  std::list<Cdt::Face_handle> border{cdt.infinite_face()};
  for (int level = 0; !border.empty(); ++level) {
    std::list<Cdt::Face_handle> next_border;
    for (auto start : border) {
      if (start->info().nesting_level != -1)
        continue;
      std::list<Cdt::Face_handle> queue{start};
      start->info().nesting_level = level;
      while (!queue.empty()) {
        auto face = queue.front();
        queue.pop_front();
        for (int i = 0; i < 3; ++i) {
          auto neighbour = face->neighbor(i);
          if (neighbour->info().nesting_level != -1)
            continue;
          if (cdt.is_constrained(Cdt::Edge(face, i))) {
            next_border.push_back(neighbour);
          } else {
            neighbour->info().nesting_level = level;
            queue.push_back(neighbour);
          }
        }
      }
    }
    border = std::move(next_border);
  }
}

}  // namespace

std::vector<std::array<int, 3>> triangulate_domain(const PlanarDomain& domain) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles(domain.points.size());
  std::vector<char> on_loop(domain.points.size(), 0);
  for (const auto& loop : domain.loops) {
    for (int index : loop) {
      const auto& p = domain.points[index];
      handles[index] = cdt.insert(Kernel::Point_2(p[0], p[1]));
      handles[index]->info() = index;
      on_loop[index] = 1;
    }
  }
  for (const auto& loop : domain.loops) {
    for (std::size_t i = 0; i < loop.size(); ++i)
      cdt.insert_constraint(handles[loop[i]], handles[loop[(i + 1) % loop.size()]]);
  }
  for (std::size_t index = 0; index < domain.points.size(); ++index) {
    if (on_loop[index])
      continue;
    const auto& p = domain.points[index];
    handles[index] = cdt.insert(Kernel::Point_2(p[0], p[1]));
    handles[index]->info() = static_cast<int>(index);
  }
  if (cdt.number_of_vertices() != domain.points.size())
    throw std::logic_error("triangulate_domain: duplicate points or Steiner points created");
  mark_domains(cdt);
  std::vector<std::array<int, 3>> triangles;
  for (auto face : cdt.finite_face_handles()) {
    if (face->info().nesting_level % 2 != 1)
      continue;
    triangles.push_back(
        {face->vertex(0)->info(), face->vertex(1)->info(), face->vertex(2)->info()});
  }
  return triangles;
}

}  // namespace holebench::generators::brep
