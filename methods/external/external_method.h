// A method that is a program: holebench writes the holed mesh to a temporary binary PLY
// file, runs the spec's command (methods/external/external_method_spec.h) and reads the
// repaired mesh it wrote; the new faces are recovered by matching faces
// (methods/external/output_patch.h). The process start and the mesh transfer are part of the
// method's time. A failure is a failed result whose message says what went wrong and ends
// with the program's last lines of stderr: a non-zero exit code (or a signal), no output file,
// an output that is not a mesh, an output that changed or dropped input faces.
#pragma once

#include "methods/external/external_method_spec.h"
#include "methods/method.h"

namespace holebench {

/// Runs `spec` on `holed` (see the file comment). Never throws for the program's failures.
MethodResult run_external_method(const Mesh& holed, const ExternalMethodSpec& spec);

class ExternalMethod final : public Method {
 public:
  explicit ExternalMethod(ExternalMethodSpec spec) : spec_(std::move(spec)) {}
  std::string id() const override { return spec_.name; }
  std::string description() const override { return "external: " + spec_.command; }
  MethodOptions options() const override {
    return MethodOptions()
        .add("command", spec_.command)
        .add("vertex_tolerance_rel_diag", spec_.vertex_tolerance_rel_diag);
  }
  MethodResult run(const Mesh& holed, const MethodParameters&, User&) const override {
    return run_external_method(holed, spec_);
  }
  const ExternalMethodSpec& spec() const { return spec_; }

 private:
  ExternalMethodSpec spec_;
};

}  // namespace holebench
