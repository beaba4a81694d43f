// Which regions are planes: the rule the generators, the B-Rep features and the label tests
// share (a region is planar where its fitted plane's rms residual is below a tolerance).
#pragma once

#include "core/plane_fit.h"

#include <vector>

namespace holebench {

/// Per region id: 1 where the region's plane fit is valid and its rms residual is below
/// `tolerance` (callers pass 1e-6 of the diagonal).
inline std::vector<char> planar_regions(const std::vector<PlaneFit>& planes, double tolerance) {
  std::vector<char> planar(planes.size(), 0);
  for (std::size_t r = 0; r < planes.size(); ++r)
    planar[r] = planes[r].valid && planes[r].plane.rms_residual < tolerance;
  return planar;
}

}  // namespace holebench
