// The one interface every hole-filling method implements. A method sees the holed mesh
// only, never the ground truth.
#pragma once

#include "core/method_result.h"
#include "methods/method_options.h"
#include "methods/user.h"

#include <memory>
#include <string>
#include <vector>

namespace holebench {

/// Settings of the experiment a method may use (never ground truth).
struct MethodParameters {
  /// The structure size delta_s (model units) of the B-Rep paper: a hole smaller than it is
  /// small enough to close automatically. 0: the method's own default.
  double structure_size = 0.0;
  /// Return the method's steps as geometry in MethodResult::layers (figures, `holebench run
  /// --layers`). Off in suite runs; a method's repair must not depend on it.
  bool record_layers = false;
};

class Method {
 public:
  virtual ~Method() = default;
  /// Stable id used in suites and records, e.g. "liepa_cgal".
  virtual std::string id() const = 0;
  /// One line for `holebench list`.
  virtual std::string description() const = 0;
  /// Every setting the method runs with (methods/method_options.h); records carry them as
  /// "method_options".
  virtual MethodOptions options() const = 0;
  /// Fills the holes of `holed`. May throw; the harness records the exception.
  virtual MethodResult run(const Mesh& holed, const MethodParameters& parameters,
                           User& user) const = 0;
};

}  // namespace holebench
