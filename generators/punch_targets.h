// Where to punch holes into a complete, segmented model: one target per kind of feature
// the model has (CASES.md, "Holes in real CAD meshes").
#pragma once

#include "core/features.h"
#include "core/mesh.h"

#include <string>
#include <vector>

namespace holebench::generators {

/// A complete model ready for punching: its mesh (region ids set by segmentation) and its
/// features.
struct AnalysedModel {
  std::string name;
  Mesh mesh;
  FeatureAnalysis features;
  double diagonal = 0.0;
  std::vector<char> region_is_planar;  ///< per region: plane fit residual below 1e-6 diag
  /// per region: the smallest region id of the planar regions that share an edge and lie in
  /// one plane with it (core/coplanar_regions.h); empty: every region is its own face.
  std::vector<int> coplanar_group;
  /// The regions are the faces of a B-Rep model (a STEP, IGES or BREP file), not a
  /// segmentation: holes punched into it keep them in the input, as the B-Rep paper's
  /// input carries its faces.
  bool regions_are_brep_faces = false;
  /// What reading the model took beyond the defaults (a B-Rep file's faces sewn, a deflection
  /// retried: occt::BrepMesh::notes), one line each.
  std::vector<std::string> notes;

  /// The face of the hole taxonomy that region `id` belongs to: coplanar regions that meet
  /// (a planar B-Rep face split in two) are one face.
  int taxonomy_face(int id) const {
    return id >= 0 && id < static_cast<int>(coplanar_group.size()) ? coplanar_group[id] : id;
  }
};

/// Segments `mesh`, assigns its region ids and analyses its features.
AnalysedModel analyse_model(std::string name, Mesh mesh, const FeatureOptions& options = {});

struct PunchTarget {
  /// "face_interior", "edge_convex", "edge_reflex", "corner_<signature>" (e.g.
  /// "corner_ccr"), "multi_feature", "curved_face", "cone_apex", "island".
  std::string kind;
  VertexHandle vertex;      ///< the hole's centre: a vertex of the complete mesh
  double min_radius = 0.0;  ///< the hole must be at least this large to reach its features
};

/// One target of each kind the model has, in a fixed order, chosen deterministically:
/// - face_interior: the vertex of a planar region farthest from any sharp edge;
/// - edge_convex / edge_reflex: the middle vertex of the longest chain of that convexity;
/// - corner_<signature>: the first corner (by vertex index) with that signature;
/// - multi_feature: a vertex near which two sharp-edge chains that share no corner come
///   closest (one hole across several features);
/// - curved_face: the vertex of a non-planar region farthest from its sharp edges;
/// - cone_apex: a vertex of a non-planar region where all its faces meet at a point whose
///   faces' normals spread over more than 90 degrees (a cone's apex);
/// - island: like face_interior (an annulus is removed there, its inside kept).
std::vector<PunchTarget> find_punch_targets(const AnalysedModel& model);

/// "gear_tooth", for a prismatic part with teeth around an axis (a gear; the slice paper's
/// figure 20, on CGAL's pinion): the axis is the coordinate axis the faces' normals point
/// along least (area-weighted: the extrusion's direction), through the bounding box's centre;
/// the target is the vertex farthest from it within a tenth of the length from the middle, a
/// tooth's tip. Not among find_punch_targets' (it means nothing on other parts); the catalog
/// lists it for the gear models only. Throws std::invalid_argument on an empty model.
PunchTarget find_gear_tooth_target(const AnalysedModel& model);

}  // namespace holebench::generators
