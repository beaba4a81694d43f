// holebench figures: the papers' figures and tables.
#include "harness/cli/subcommands.h"
#include "harness/figures/paper_figures.h"
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
               "holebench figures: the pictures only; Table 2 (both forms) and the crease "
               "table need --results of the paper suite (holebench run --suite paper --out "
               "DIR)\n");
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
      "Regenerate the papers' figures and tables. Rendered (methods run on the cases, "
      "deterministic; a PNG, an SVG and a caption file each): B-Rep figure 5; slice paper "
      "figures 2 (the method's steps), 17-20 (Table 2's models), 22 (noise), 23-24 (cone "
      "apex); crest-line paper figures 10 and 13 (crease holes) and 12 (concave corner). With "
      "--results of the paper suite: the slice paper's Table 2 (its four rows beside ours, and "
      "per CAD model and target kind) and the crease table");
  command->add_option("--out", flags->options.out_dir, "Output folder")->required();
  command
      ->add_option("--figure", flags->options.only,
                   "Render only these figures, repeatable: figure2, figure5, figure10, "
                   "figure12, figure13, figure17 .. figure20, figure22, figure23 (with 24) "
                   "(default: all, about 10 s)")
      ->type_name("NAME");
  command
      ->add_option("--panel-size", flags->options.panel_size,
                   "Pixels of each square panel (default 300)")
      ->check(CLI::Range(32, 4096));
  command
      ->add_option("--results", flags->results,
                   "results.json of the paper suite (holebench run --suite paper)")
      ->check(CLI::ExistingFile);
  return {command, [flags] { return figures(*flags); }};
}

}  // namespace holebench::harness::cli
