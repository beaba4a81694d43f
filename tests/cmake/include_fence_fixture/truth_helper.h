// A fixture for the ground-truth fence, never compiled: a helper header that includes the
// ground truth, as a method's own header might (cmake/check_include_fence.cmake).
#pragma once

#include "core/case.h"
