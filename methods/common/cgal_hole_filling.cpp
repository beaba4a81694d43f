// The only translation unit that includes CGAL's hole filling (about 25 s to compile).
#include "methods/common/cgal_hole_filling.h"

#include "core/boundary_loops.h"
#include "core/stopwatch.h"

// CGAL's graph traits for OpenMesh must come before any CGAL algorithm header.
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>

#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>

#include <iterator>

namespace holebench {

namespace PMP = CGAL::Polygon_mesh_processing;

const char* cgal_function_name(CgalHoleSteps steps) {
  switch (steps) {
    case CgalHoleSteps::Triangulate:
      return "triangulate_hole";
    case CgalHoleSteps::TriangulateRefine:
      return "triangulate_and_refine_hole";
    case CgalHoleSteps::TriangulateRefineFair:
      return "triangulate_refine_and_fair_hole";
  }
  return "unknown";
}

MethodResult fill_holes_cgal(const Mesh& holed, const CgalHoleFillingOptions& options) {
  const auto start = SteadyClock::now();
  MethodResult result;
  result.repaired = holed;
  Mesh& mesh = result.repaired;

  // Loops are found once, before any filling; filling one hole adds elements but does
  // not invalidate the handles of the others (OpenMesh's array kernel).
  const std::vector<BoundaryLoop> loops = find_boundary_loops(mesh);
  std::size_t closed = 0;
  for (std::size_t i = 0; i < loops.size(); ++i) {
    HoleReport report;
    report.hole_index = static_cast<int>(i);
    report.loop_size = loops[i].size();
    report.centroid = loop_centroid(mesh, loops[i]);
    std::vector<FaceHandle> faces;
    std::vector<VertexHandle> vertices;
    const HalfedgeHandle border = loops[i].halfedges.front();
    const auto params = CGAL::parameters::density_control_factor(options.density_control_factor)
                            .fairing_continuity(options.fairing_continuity)
                            .use_delaunay_triangulation(options.use_delaunay_triangulation)
                            .use_2d_constrained_delaunay_triangulation(
                                options.use_2d_constrained_delaunay_triangulation);
    bool fair_ok = true;
    switch (options.steps) {
      case CgalHoleSteps::TriangulateRefineFair:
        fair_ok = std::get<0>(PMP::triangulate_refine_and_fair_hole(
            mesh, border, std::back_inserter(faces), std::back_inserter(vertices), params));
        break;
      case CgalHoleSteps::TriangulateRefine:
        PMP::triangulate_and_refine_hole(mesh, border, std::back_inserter(faces),
                                         std::back_inserter(vertices), params);
        break;
      case CgalHoleSteps::Triangulate:
        PMP::triangulate_hole(mesh, border, std::back_inserter(faces), params);
        break;
    }
    report.new_faces = faces.size();
    report.new_vertices = vertices.size();
    report.closed = !faces.empty();
    if (!report.closed)
      report.note = "CGAL found no triangulation of the hole";
    else if (!fair_ok) {
      // CGAL keeps the refined patch unfaired when its fairing solver fails.
      report.note = "triangulated and refined; fairing failed";
      report.fallback = "refined_without_fairing";
    }
    closed += report.closed ? 1 : 0;
    result.holes.push_back(std::move(report));
  }
  result.status = closed == loops.size()          ? MethodStatus::Ok
                  : closed == 0 && !loops.empty() ? MethodStatus::Failed
                                                  : MethodStatus::Partial;
  if (result.status != MethodStatus::Ok) {
    result.message = std::to_string(loops.size() - closed) + " of " + std::to_string(loops.size()) +
                     " holes left open";
  }
  result.phases.push_back({cgal_function_name(options.steps), seconds_since(start)});
  return result;
}

}  // namespace holebench
