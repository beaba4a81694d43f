// Procedural solids that give the features the CGAL data set may lack: reflex edges and
// mixed corners (orthogonal solids built from voxels) and curved faces (a cylinder, a cone
// with its apex). All closed, outward oriented, deterministic, `Provenance::Original`.
#pragma once

#include "core/mesh.h"

#include <array>
#include <string>
#include <vector>

namespace holebench::generators {

struct OrthogonalSolidOptions {
  std::vector<std::array<int, 3>> voxels;  ///< unit cells (i, j, k) that are solid
  double voxel_size = 1.0;
  int subdivisions = 20;  ///< grid cells per voxel edge on each face
};

/// The boundary of a union of voxels, each face of it a grid of right triangles, regions
/// by dihedral segmentation (one per planar face of the solid). Voxels must touch only by
/// whole faces where they touch (no edge-only or vertex-only contact: that would make the
/// surface non-manifold).
Mesh make_orthogonal_solid(const OrthogonalSolidOptions& options);

struct RevolvedSolidOptions {
  double radius = 1.0;
  double height = 2.0;
  int segments = 96;      ///< around the axis
  double spacing = 0.05;  ///< target edge length along the height and across the caps
};

/// A closed cylinder along z from 0 to height: the side (region 0, curved), the top (1)
/// and the bottom (2).
Mesh make_cylinder(const RevolvedSolidOptions& options);

/// A closed cone along z: base disc at z = 0 (region 1), apex at z = height; the side is
/// region 0 (curved, meeting at the apex).
Mesh make_cone(const RevolvedSolidOptions& options);

/// A square cross section swept along a helix (the slice paper's figure 18, "a helical
/// surface with a square cross section"): the square, of side `side`, lies in the plane of
/// the axis (z) and the radial direction, centred on the helix of radius `radius` that rises
/// `pitch` per turn, for `turns` turns; closed by two planar end caps. Four curved faces
/// (two cylinders, two helicoids) meet at convex sharp edges.
struct HelicalSweepOptions {
  double radius = 2.0;
  double side = 0.6;
  double pitch = 1.5;  ///< must exceed `side`, so that the turns do not touch
  double turns = 1.25;
  int steps = 400;      ///< along the helix
  int side_steps = 12;  ///< across each side of the square (and each cap)
};
Mesh make_helical_sweep(const HelicalSweepOptions& options = {});

/// The named procedural solids of the catalog: "l_block", "stepped_block",
/// "notched_block", "block_on_plate", "cylinder", "cone", "helical_sweep".
std::vector<std::string> procedural_solid_names();
/// Throws std::invalid_argument for an unknown name.
Mesh make_procedural_solid(const std::string& name);

}  // namespace holebench::generators
