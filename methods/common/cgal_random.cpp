#include "methods/common/cgal_random.h"

#include <CGAL/Random.h>

namespace holebench {

void seed_cgal_default_random(unsigned seed) {
  CGAL::get_default_random() = CGAL::Random(seed);
}

}  // namespace holebench
