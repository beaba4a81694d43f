// A fixture for the ground-truth fence (cmake/check_include_fence.cmake), never compiled: a
// method file that reaches the ground truth through a header of its own. The test
// include_fence_catches_a_method_that_reads_the_truth expects the check to name this file
// and the chain of includes.
#include "tests/cmake/include_fence_fixture/truth_helper.h"

int cheating_method() {
  return 0;
}
