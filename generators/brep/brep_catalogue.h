// The catalogue of synthetic B-Rep cases: one recipe per case stem (each made small and
// large), in a fixed order.
#pragma once

#include "generators/brep/polyhedron.h"

#include <functional>
#include <string>
#include <variant>
#include <vector>

namespace holebench::generators::brep {

/// What a ball hole is punched around.
enum class Target { Face, Edge, Vertex };

/// A hole punched by a ball around a face-interior point, an edge point or a vertex.
struct BallSpec {
  std::function<Polyhedron()> model;
  Point center{0, 0, 0};
  Target target = Target::Face;
  double small_radius = 0.5;
  double large_radius = 1.5;
};

/// Whether the faces a RemovalSpec names are removed or are the only ones kept.
enum class NamedFaces { Removed, Kept };

/// A hole left by removing whole faces (given by a point inside each).
struct RemovalSpec {
  std::function<Polyhedron()> model;
  std::vector<Point> faces;
  NamedFaces named = NamedFaces::Removed;
};

struct Recipe {
  std::string stem;    ///< the id without "/small" or "/large"
  std::string kind;    ///< the stem's first two parts, e.g. "k2/inner"
  std::string target;  ///< HoleTruth::target
  std::string combo;   ///< expected label combination (see combo_of); checked on generation
  std::string weak_spot;
  std::string description;
  std::variant<BallSpec, RemovalSpec> spec;
};

/// Every recipe, in the catalogue's order.
const std::vector<Recipe>& brep_recipes();

}  // namespace holebench::generators::brep
