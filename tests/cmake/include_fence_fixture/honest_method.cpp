// A fixture for the ground-truth fence, never compiled: a method file that includes only what
// a method may see (the mesh and the labels' vocabulary); the check must not name it.
#include "core/hole_labels.h"
#include "core/mesh.h"

int honest_method() {
  return 0;
}
