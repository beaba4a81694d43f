// A fixture for the ground-truth fence, never compiled: the ground truth included with angle
// brackets (the project root is on the include path); the check must name it.
#include <core/case.h>

int angle_method() {
  return 0;
}
