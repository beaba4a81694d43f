#include "methods/cgal_triangulate/cgal_triangulate.h"

#include "methods/common/cgal_hole_filling.h"

namespace holebench {

MethodResult fill_holes_cgal_triangulate(const Mesh& holed, const CgalTriangulateOptions& options) {
  CgalHoleFillingOptions cgal;
  cgal.steps = CgalHoleSteps::Triangulate;
  cgal.use_delaunay_triangulation = options.use_delaunay_triangulation;
  cgal.use_2d_constrained_delaunay_triangulation =
      options.use_2d_constrained_delaunay_triangulation;
  return fill_holes_cgal(holed, cgal);
}

MethodOptions CgalTriangulateMethod::options() const {
  return MethodOptions()
      .add("use_delaunay_triangulation", options_.use_delaunay_triangulation)
      .add("use_2d_constrained_delaunay_triangulation",
           options_.use_2d_constrained_delaunay_triangulation);
}

}  // namespace holebench
