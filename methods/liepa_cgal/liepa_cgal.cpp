#include "methods/liepa_cgal/liepa_cgal.h"

#include "methods/common/cgal_hole_filling.h"

namespace holebench {

MethodResult fill_holes_liepa_cgal(const Mesh& holed, const LiepaCgalOptions& options) {
  CgalHoleFillingOptions cgal;
  cgal.steps = !options.refine ? CgalHoleSteps::Triangulate
               : options.fair  ? CgalHoleSteps::TriangulateRefineFair
                               : CgalHoleSteps::TriangulateRefine;
  cgal.density_control_factor = options.density_control_factor;
  cgal.fairing_continuity = options.fairing_continuity;
  cgal.use_delaunay_triangulation = false;  // determinism (docs/methods.md)
  return fill_holes_cgal(holed, cgal);
}

MethodOptions LiepaCgalMethod::options() const {
  return MethodOptions()
      .add("refine", options_.refine)
      .add("fair", options_.fair)
      .add("density_control_factor", options_.density_control_factor)
      .add("fairing_continuity", options_.fairing_continuity);
}

}  // namespace holebench
