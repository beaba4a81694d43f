#include "methods/external/predefined_external_methods.h"

#ifndef HOLEBENCH_EXTERNAL_METHODS_DIR
#define HOLEBENCH_EXTERNAL_METHODS_DIR "methods/external"
#endif

namespace holebench {

std::vector<ExternalMethodSpec> predefined_external_methods() {
  ExternalMethodSpec meshlab;
  meshlab.name = "meshlab_close_holes";
  // meshlabserver needs an X display even without a window: xvfb-run -a gives it one.
  meshlab.command = std::string("xvfb-run -a meshlabserver -i {input} -o {output} -s '") +
                    HOLEBENCH_EXTERNAL_METHODS_DIR + "/meshlab_close_holes.mlx'";
  meshlab.vertex_tolerance_rel_diag = 1e-6;
  meshlab.required_programs = {"xvfb-run", "meshlabserver"};
  return {meshlab};
}

std::optional<ExternalMethodSpec> find_predefined_external_method(const std::string& name) {
  for (auto& spec : predefined_external_methods()) {
    if (spec.name == name)
      return spec;
  }
  return std::nullopt;
}

}  // namespace holebench
