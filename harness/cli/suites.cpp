// holebench suites: each suite's name and description.
#include "harness/cli/subcommands.h"
#include "harness/run/suite.h"

#include <fmt/format.h>

namespace holebench::harness::cli {

namespace {

int list_suites_with_descriptions() {
  for (const auto& name : list_suites()) {
    const auto suite = load_suite(name);
    fmt::print("{:<10} {}\n", name, suite.description);
  }
  return 0;
}

}  // namespace

Subcommand add_suites_command(CLI::App& app) {
  auto* command = app.add_subcommand("suites", "List the suites (suites/*.json)");
  return {command, list_suites_with_descriptions};
}

}  // namespace holebench::harness::cli
