// Baseline: the way a CAD system fills a hole, OpenCASCADE's N-sided plate filling
// (GeomPlate, the engine under BRepOffsetAPI_MakeFilling). Each hole's boundary vertices are
// G0 constraints and the surrounding surface's normals there G1 constraints; the plate
// surface deforms the hole's least-squares plane to meet them. The patch is tessellated in
// the plate's parameter domain (the plane's coordinates) by a constrained Delaunay
// triangulation whose boundary is the hole's own loop, so it is sewn to the hole exactly.
// It knows nothing of sharp features. docs/methods.md#occt_fill.
#pragma once

#include "methods/method.h"

namespace holebench {

struct OcctFillOptions {
  /// At most this many boundary vertices, evenly spread along each loop, become plate
  /// constraints (the plate's linear system grows with the cube of their number).
  int max_constraints = 48;
  /// G1 (the surface's normal at the boundary) as well as G0; off: the boundary points only.
  bool tangent_constraints = true;
  /// The G1 normals fitted as the gradient of a quadric over two rings of faces (on, see
  /// occt_fill.cpp:fitted_normal) rather than the mean normal of the faces at the vertex,
  /// which lie on one side of it and tilt it away from the hole.
  bool fitted_normals = true;
  double normal_fit_max_angle = 0.5;    ///< radians: faces further from the mean are left out
  int degree = 3;                       ///< GeomPlate_BuildPlateSurface's degree
  int iterations = 2;                   ///< its NbIter
  double interior_spacing_edges = 1.0;  ///< interior points, in mean boundary-edge lengths
  /// A triangle edge between two boundary vertices that the mesh already joins (an inner
  /// edge) gets a Steiner point at its middle, and the domain is triangulated again, at most
  /// this many times.
  int max_chord_split_rounds = 8;
  /// An island loop (one whose points all lie inside another loop, seen along that loop's
  /// plane normal, and within its diameter) is filled with the hole around it: the patch
  /// covers the region between the two. Off: every loop is filled on its own.
  bool attach_islands = true;
};

/// Fills every hole of `holed` with a plate surface. New faces and vertices are
/// `Provenance::New`; the input is unchanged. A hole that cannot be filled is left open, and
/// its report says why (plate not computed, boundary folds over in the plate's domain, a
/// facet would be non-manifold).
MethodResult fill_holes_occt_plate(const Mesh& holed, const OcctFillOptions& options = {});

class OcctFillMethod final : public Method {
 public:
  explicit OcctFillMethod(OcctFillOptions options = {}) : options_(options) {}
  std::string id() const override { return "occt_fill"; }
  std::string description() const override {
    return "baseline: OpenCASCADE N-sided plate filling (GeomPlate, G0 + G1 along the hole), "
           "no feature handling";
  }
  MethodOptions options() const override;
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override {
    return fill_holes_occt_plate(holed, options_);
  }

 private:
  OcctFillOptions options_;
};

}  // namespace holebench
