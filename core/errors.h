// The exceptions holebench throws. Each derives from a standard exception so
// that callers may catch broadly; the harness turns them into job statuses.
#pragma once

#include <stdexcept>
#include <string>

namespace holebench {

/// Input that holebench cannot use: a missing file, a file that is not a mesh,
/// NaN coordinates, non-manifold topology. `what()` names the file and the place.
class InvalidInputError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// An algorithm could not produce its result (for example a hole it could not fill).
class AlgorithmError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace holebench
