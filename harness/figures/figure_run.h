// A method run on a case for a figure, as a job runs it (harness/run/job.cpp): the same
// structure size, the same CGAL seed, the named user, and the method's layers when asked.
// Methods are deterministic, so the figure shows the result the run's records measured.
#pragma once

#include "core/case.h"
#include "core/method_result.h"

#include <string>

namespace holebench::harness {

MethodResult run_method_for_figure(const std::string& method_id, const Case& c,
                                   const std::string& user = "no_user", bool layers = false);

}  // namespace holebench::harness
