// holebench list: the methods, the predefined external methods and the case families.
#include "harness/cli/subcommands.h"
#include "methods/external/predefined_external_methods.h"
#include "methods/registry.h"

#include <fmt/format.h>

namespace holebench::harness::cli {

namespace {

int list_methods_and_families() {
  fmt::print("methods:\n");
  for (const auto& m : make_all_methods())
    fmt::print("  {:<16} {}\n", m->id(), m->description());
  fmt::print("variants run by name only (--method ID):\n");
  for (const auto& m : make_methods_run_by_name())
    fmt::print("  {:<16} {}\n", m->id(), m->description());
  fmt::print("external methods holebench predefines (run by name: --method NAME):\n");
  for (const auto& spec : predefined_external_methods())
    fmt::print("  {:<16} {}\n", spec.name, spec.command);
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
