#include "harness/figures/figure_run.h"

#include "harness/run/oracle_user.h"
#include "methods/common/cgal_random.h"
#include "methods/registry.h"

namespace holebench::harness {

MethodResult run_method_for_figure(const std::string& method_id, const Case& c,
                                   const std::string& user, bool layers) {
  const auto method = make_method(method_id);
  const auto answering = make_user(user, c);
  MethodParameters parameters;
  parameters.structure_size = c.parameters.structure_size;
  parameters.record_layers = layers;
  seed_cgal_default_random();
  return method->run(c.input, parameters, *answering);
}

}  // namespace holebench::harness
