// holebench cases list | export | gallery: the catalog's cases, listed, written as files or
// drawn.
#include "core/labels_summary.h"
#include "generators/case_catalog.h"
#include "harness/cli/common_flags.h"
#include "harness/cli/subcommands.h"
#include "harness/outputs/case_export.h"
#include "harness/outputs/case_gallery.h"
#include "harness/outputs/file_names.h"
#include "harness/run/case_selection.h"

#include <fmt/format.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace holebench::harness::cli {

namespace {

using generators::CaseCatalog;

struct CasesFlags {
  generators::CatalogOptions catalog;
  bool no_cad = false;
  std::vector<std::string> patterns;  ///< shared by list, export and gallery
  bool labels = false;                ///< list --labels
  std::filesystem::path export_dir;
  double export_noise = 0.0;
  std::uint64_t export_seed = 0;
  std::filesystem::path gallery_dir;
};

int cases_list(const CaseCatalog& catalog, const std::vector<std::string>& patterns, bool labels) {
  const auto selected =
      select_cases(catalog, patterns.empty() ? std::vector<std::string>{"*"} : patterns);
  for (const auto& c : selected) {
    std::string extra;
    if (labels)
      extra = "  " + labels_summary(catalog.make(c.id));
    fmt::print("{:<48} {}{}\n", c.id, c.description, extra);
  }
  print_catalog_notes(catalog);
  std::fprintf(stderr, "%zu cases\n", selected.size());
  return 0;
}

int cases_export(const CaseCatalog& catalog, const std::vector<std::string>& patterns,
                 const std::filesystem::path& dir, double noise, std::uint64_t seed) {
  const auto selected =
      select_cases(catalog, patterns.empty() ? std::vector<std::string>{"*"} : patterns);
  for (std::size_t i = 0; i < selected.size(); ++i) {
    const auto c = catalog.make(selected[i].id, seed, noise);
    export_case(c, dir / file_stem_of_id(c.id));
    std::fprintf(stderr, "[%zu/%zu] %s\n", i + 1, selected.size(), c.id.c_str());
  }
  print_catalog_notes(catalog);
  return 0;
}

int cases_gallery(const CaseCatalog& catalog, const std::vector<std::string>& patterns,
                  const std::filesystem::path& dir) {
  const auto selected =
      select_cases(catalog, patterns.empty() ? std::vector<std::string>{"brep/*"} : patterns);
  const auto page = write_case_gallery(catalog, selected, dir);
  fmt::print("{}\n", page.string());
  return 0;
}

}  // namespace

Subcommand add_cases_command(CLI::App& app) {
  auto flags = std::make_shared<CasesFlags>();
  auto* cases = app.add_subcommand("cases", "List or export cases");
  cases->require_subcommand(1);
  auto* list = cases->add_subcommand("list", "List cases (optionally matching patterns)");
  list->add_option("patterns", flags->patterns, "Case ids or patterns (default: all)");
  list->add_flag("--labels", flags->labels, "Generate each case and print its labels");
  add_catalog_flags(list, flags->catalog, flags->no_cad);

  auto* export_command =
      cases->add_subcommand("export", "Write cases as PLY/OFF meshes and JSON ground truth");
  export_command->add_option("dir", flags->export_dir, "Output folder")->required();
  export_command->add_option("patterns", flags->patterns, "Case ids or patterns (default: all)");
  export_command
      ->add_option("--noise", flags->export_noise, "Noise level in % of 1 % of the diagonal")
      ->check(CLI::NonNegativeNumber);
  export_command->add_option("--seed", flags->export_seed, "Noise seed");
  add_catalog_flags(export_command, flags->catalog, flags->no_cad);

  auto* gallery = cases->add_subcommand(
      "gallery", "Render one picture per case (figure-5 style) and a gallery.html page");
  gallery->add_option("dir", flags->gallery_dir, "Output folder")->required();
  gallery->add_option("patterns", flags->patterns, "Case ids or patterns (default: brep/*)");
  add_catalog_flags(gallery, flags->catalog, flags->no_cad);

  return {cases, [flags, list, export_command, gallery] {
            auto catalog_options = flags->catalog;
            catalog_options.include_cad = !flags->no_cad;
            catalog_options.families = families_of_patterns(flags->patterns);
            if (list->parsed())
              return cases_list(CaseCatalog(catalog_options), flags->patterns, flags->labels);
            if (export_command->parsed()) {
              return cases_export(CaseCatalog(catalog_options), flags->patterns, flags->export_dir,
                                  flags->export_noise, flags->export_seed);
            }
            if (gallery->parsed())
              return cases_gallery(CaseCatalog(catalog_options), flags->patterns,
                                   flags->gallery_dir);
            return 0;
          }};
}

}  // namespace holebench::harness::cli
