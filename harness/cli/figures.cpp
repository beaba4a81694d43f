// holebench figures: the papers' figures and tables.
#include "harness/cli/subcommands.h"
#include "harness/outputs/paper_figures.h"
#include "harness/results/results_reader.h"

#include <fmt/format.h>

#include <filesystem>
#include <memory>

namespace holebench::harness::cli {

namespace {

struct FiguresFlags {
  FiguresOptions options;
  std::filesystem::path results;
};

int figures(FiguresFlags& flags) {
  auto& options = flags.options;
  if (!flags.results.empty())
    options.results = flags.results;
  for (const auto& path : write_paper_figures(options))
    fmt::print("{}\n", path.string());
  if (!options.results) {
    fmt::print(stderr,
               "holebench figures: only figure 5 (it needs no results); Table 2 and the "
               "crease table need --results of the paper suite (holebench run --suite paper "
               "--out DIR)\n");
  } else {
    const auto data = read_results_json(*options.results);
    for (const auto& gap : paper_figure_gaps(data))
      fmt::print(stderr, "holebench figures: {} (run the paper suite)\n", gap);
  }
  return 0;
}

}  // namespace

Subcommand add_figures_command(CLI::App& app) {
  auto flags = std::make_shared<FiguresFlags>();
  auto* command = app.add_subcommand(
      "figures",
      "Regenerate the papers' figures and tables: B-Rep figure 5 (rendered), and with "
      "--results the slice paper's Table 2 and the crest-line paper's figures 10/13 setting");
  command->add_option("--out", flags->options.out_dir, "Output folder")->required();
  command
      ->add_option("--results", flags->results,
                   "results.json of the paper suite (holebench run --suite paper)")
      ->check(CLI::ExistingFile);
  return {command, [flags] { return figures(*flags); }};
}

}  // namespace holebench::harness::cli
