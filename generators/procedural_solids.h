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

/// The named procedural solids of the catalog: "l_block", "stepped_block",
/// "notched_block", "block_on_plate", "cylinder", "cone".
std::vector<std::string> procedural_solid_names();
/// Throws std::invalid_argument for an unknown name.
Mesh make_procedural_solid(const std::string& name);

}  // namespace holebench::generators
