// A fixture for the ground-truth fence, never compiled: the ground truth included by a path
// relative to this file's folder; the check must name it.
#include "../../../core/case.h"

int relative_method() {
  return 0;
}
