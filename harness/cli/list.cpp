// holebench list: the methods, the predefined external methods and the case families.
#include "harness/cli/subcommands.h"
#include "methods/external/predefined_external_methods.h"
#include "methods/registry.h"

#include <fmt/format.h>

#include <algorithm>

namespace holebench::harness::cli {

namespace {

int list_methods_and_families() {
  const auto methods = make_all_methods();
  const auto variants = make_named_variants();
  const auto ablation = make_ablation_methods();
  const auto external = predefined_external_methods();
  std::size_t width = 16;  // one column of names for the three lists
  for (const auto* list : {&methods, &variants, &ablation}) {
    for (const auto& m : *list)
      width = std::max(width, m->id().size());
  }
  for (const auto& spec : external)
    width = std::max(width, spec.name.size());
  fmt::print("methods (the papers' steps as written, and the baselines):\n");
  for (const auto& m : methods)
    fmt::print("  {:<{}} {}\n", m->id(), width, m->description());
  fmt::print("named variants with the project's departures, run by name only (--method ID):\n");
  for (const auto& m : variants)
    fmt::print("  {:<{}} {}\n", m->id(), width, m->description());
  fmt::print("the slice paper's Table 2 ablation, run by name only (suite slice_ablation):\n");
  for (const auto& m : ablation)
    fmt::print("  {:<{}} {}\n", m->id(), width, m->description());
  fmt::print("external methods holebench predefines (run by name: --method NAME):\n");
  for (const auto& spec : external)
    fmt::print("  {:<{}} {}\n", spec.name, width, spec.command);
  fmt::print(
      "case families (see `holebench cases list`):\n"
      "  box/<target>                  the walking skeleton's box holes\n"
      "  brep/...                      synthetic planar B-Rep cases, k <= 3 and variants\n"
      "  solid/<name>/<target>/<size>  holes in procedural solids\n"
      "  cad/<model>/<target>/<size>   holes in CGAL's CAD meshes\n"
      "  file/<stem>/<target>/<size>   holes in your own meshes (--mesh)\n");
  return 0;
}

}  // namespace

Subcommand add_list_command(CLI::App& app) {
  auto* command = app.add_subcommand("list", "List the methods and the case families");
  return {command, list_methods_and_families};
}

}  // namespace holebench::harness::cli
