// Building the core mesh from an indexed triangle list, with every check that
// keeps later stages from crashing on bad data.
#pragma once

#include "core/mesh.h"

#include <array>
#include <string>
#include <vector>

namespace holebench {

/// An indexed triangle list: what a file reader or a generator produces.
struct TriangleSoup {
  std::vector<Point> points;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> regions;  ///< empty, or one region id per triangle
};

struct BuildOptions {
  std::string source = "<memory>";  ///< named in error messages (a file path)
  bool mark_original = true;        ///< mark every element `Provenance::Original`
};

/// Builds the core mesh from `soup`, vertex i of the soup being vertex i of the mesh
/// and triangle j face j.
/// Throws InvalidInputError, naming `options.source` and the element, on: no triangles,
/// NaN or infinite coordinates, out-of-range indices, a triangle that repeats a vertex or
/// has zero area, an edge shared by more than two triangles (non-manifold edge), two
/// triangles that traverse an edge in the same direction (inconsistent orientation), a
/// vertex whose triangles do not form one fan (non-manifold vertex), a region list of
/// the wrong length.
Mesh build_mesh(const TriangleSoup& soup, const BuildOptions& options = {});

/// The inverse of build_mesh: points, triangles and region ids of `mesh` (deleted
/// elements skipped, indices compacted in handle order).
TriangleSoup to_soup(const Mesh& mesh);

}  // namespace holebench
