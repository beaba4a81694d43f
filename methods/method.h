// The one interface every hole-filling method implements. A method sees the holed mesh
// only, never the ground truth.
#pragma once

#include "core/mesh.h"
#include "methods/user.h"

#include <memory>
#include <string>
#include <vector>

namespace holebench {

enum class MethodStatus {
  Ok,       ///< every hole handled as the method intends
  Partial,  ///< some holes were left open or only partly handled (see the hole reports)
  Failed,   ///< no usable result
};
const char* to_string(MethodStatus status);

/// What a method did with one boundary loop of its input.
struct HoleReport {
  int hole_index = 0;         ///< index in the method's own detection order
  std::size_t loop_size = 0;  ///< boundary edges of the hole
  bool closed = false;        ///< the method produced faces that close it
  std::size_t new_faces = 0;
  std::size_t new_vertices = 0;
  std::string note;  ///< what went wrong, or what the method decided
};

struct PhaseTiming {
  std::string phase;  ///< a step named as in the method's paper
  double seconds = 0.0;
};

struct MethodResult {
  Mesh repaired;  ///< the input with the method's patches; new elements are `Provenance::New`
  std::vector<HoleReport> holes;
  MethodStatus status = MethodStatus::Ok;
  std::string message;
  std::vector<PhaseTiming> phases;
};

class Method {
 public:
  virtual ~Method() = default;
  /// Stable id used in suites and records, e.g. "liepa_cgal".
  virtual std::string id() const = 0;
  /// One line for `holebench list`.
  virtual std::string description() const = 0;
  /// Fills the holes of `holed`. May throw; the harness records the exception.
  virtual MethodResult run(const Mesh& holed, User& user) const = 0;
};

}  // namespace holebench
