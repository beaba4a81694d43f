#include "harness/run/resolve_run_options.h"

#include "core/errors.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace holebench::harness {
namespace {

const std::filesystem::path kSuitesDir = std::filesystem::path(HOLEBENCH_SOURCE_DIR) / "suites";

ExternalMethodSpec external(const std::string& name) {
  ExternalMethodSpec spec;
  spec.name = name;
  spec.command = "true {input} {output}";
  return spec;
}

// A suite whose every field differs from the built-in defaults, so that a field taken from it
// cannot be told apart from a default by accident.
Suite unusual_suite() {
  Suite suite;
  suite.name = "unusual";
  suite.case_patterns = {"box/*"};
  suite.methods = {"liepa_cgal"};
  suite.external_methods = {external("from_suite")};
  suite.users = {"oracle"};
  suite.noise_levels = {5.0, 25.0};
  suite.seeds = {3};
  suite.include_cad = false;
  suite.timeout_seconds = 42.0;
  suite.memory_limit_bytes = 123456789;
  suite.method_repetitions = 3;
  suite.evaluation.hausdorff_error_bound_rel_diag = 2e-3;
  return suite;
}

// Without flags, a run is the suite's: every field the suite has comes through unchanged.
TEST(ResolveRunOptions, WithoutFlagsTheSuiteDecides) {
  RunFlags flags;
  flags.out_dir = "out";
  const RunOptions options = resolve_run_options(unusual_suite(), flags);
  EXPECT_EQ(options.out_dir, "out");
  EXPECT_EQ(options.suite.name, "unusual");
  EXPECT_EQ(options.suite.case_patterns, std::vector<std::string>{"box/*"});
  EXPECT_EQ(options.suite.methods, std::vector<std::string>{"liepa_cgal"});
  ASSERT_EQ(options.suite.external_methods.size(), 1u);
  EXPECT_EQ(options.suite.external_methods[0].name, "from_suite");
  EXPECT_EQ(options.suite.users, std::vector<std::string>{"oracle"});
  EXPECT_EQ(options.suite.noise_levels, (std::vector<double>{5.0, 25.0}));
  EXPECT_EQ(options.suite.seeds, std::vector<std::uint64_t>{3});
  EXPECT_FALSE(options.suite.include_cad);
  EXPECT_EQ(options.suite.timeout_seconds, 42.0);
  EXPECT_EQ(options.suite.memory_limit_bytes, 123456789u);
  EXPECT_EQ(options.suite.method_repetitions, 3);
  EXPECT_EQ(options.suite.evaluation.hausdorff_error_bound_rel_diag, 2e-3);
  // What a suite does not say: the flags' defaults.
  EXPECT_TRUE(options.snapshots);
  EXPECT_TRUE(options.viewer_meshes);
  EXPECT_EQ(options.workers, 0);
  EXPECT_FALSE(options.resume);
  EXPECT_EQ(options.shard.index, 0u);
  EXPECT_EQ(options.shard.count, 1u);
}

// Every flag given overrides its field of the suite; --external runs after the suite's.
TEST(ResolveRunOptions, EachFlagGivenOverridesTheSuite) {
  RunFlags flags;
  flags.case_patterns = {"brep/k3/*"};
  flags.method_ids = {"slice_loft", "crest_feature"};
  flags.external_methods = {external("from_flag")};
  flags.noise_levels = std::vector<double>{0.0};
  flags.seeds = std::vector<std::uint64_t>{7, 8};
  flags.users = std::vector<std::string>{"no_user"};
  flags.hausdorff_error_bound_rel_diag = 1e-5;
  flags.timeout_seconds = 0.0;  // 0: no limit, a value like any other
  flags.memory_limit_bytes = 0;
  flags.method_repetitions = 5;
  flags.shard = ShardSpec{2, 4};
  flags.cad_data_dir = "cad";
  flags.no_snapshots = true;
  flags.no_viewer_meshes = true;
  flags.workers = 2;
  flags.resume = true;
  const RunOptions options = resolve_run_options(unusual_suite(), flags);
  EXPECT_EQ(options.suite.name, "unusual");
  EXPECT_EQ(options.suite.case_patterns, std::vector<std::string>{"brep/k3/*"});
  EXPECT_EQ(options.suite.methods, (std::vector<std::string>{"slice_loft", "crest_feature"}));
  ASSERT_EQ(options.suite.external_methods.size(), 2u);
  EXPECT_EQ(options.suite.external_methods[0].name, "from_suite");
  EXPECT_EQ(options.suite.external_methods[1].name, "from_flag");
  EXPECT_EQ(options.suite.noise_levels, std::vector<double>{0.0});
  EXPECT_EQ(options.suite.seeds, (std::vector<std::uint64_t>{7, 8}));
  EXPECT_EQ(options.suite.users, std::vector<std::string>{"no_user"});
  EXPECT_EQ(options.suite.evaluation.hausdorff_error_bound_rel_diag, 1e-5);
  EXPECT_EQ(options.suite.timeout_seconds, 0.0);
  EXPECT_EQ(options.suite.memory_limit_bytes, 0u);
  EXPECT_EQ(options.suite.method_repetitions, 5);
  EXPECT_EQ(options.shard.index, 2u);
  EXPECT_EQ(options.shard.count, 4u);
  EXPECT_EQ(options.cad_data_dir, "cad");
  EXPECT_FALSE(options.snapshots);
  EXPECT_FALSE(options.viewer_meshes);
  EXPECT_EQ(options.workers, 2);
  EXPECT_TRUE(options.resume);
}

// --no-cad only ever leaves the CAD models out; without it the suite's choice stands.
TEST(ResolveRunOptions, NoCadLeavesOutButNeverBringsIn) {
  Suite with_cad = unusual_suite();
  with_cad.include_cad = true;
  RunFlags flags;
  EXPECT_TRUE(resolve_run_options(with_cad, flags).suite.include_cad);
  EXPECT_FALSE(resolve_run_options(unusual_suite(), flags).suite.include_cad);
  flags.no_cad = true;
  EXPECT_FALSE(resolve_run_options(with_cad, flags).suite.include_cad);
}

// A suite may name the user's model folders ("meshes", as the kicad suite does); --mesh
// replaces them; a folder that does not exist is an error naming the suite and the field.
TEST(ResolveRunOptions, TheSuitesMeshesUnlessMeshIsGiven) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_suite_meshes";
  std::filesystem::create_directories(dir);
  Suite suite = unusual_suite();
  suite.meshes = {dir};
  EXPECT_EQ(resolve_run_options(suite, RunFlags{}).suite.meshes,
            std::vector<std::filesystem::path>{dir});
  RunFlags flags;
  flags.user_meshes = {"part.step"};
  EXPECT_EQ(resolve_run_options(suite, flags).suite.meshes,
            std::vector<std::filesystem::path>{"part.step"});
  suite.meshes = {dir, dir / "no_such_folder"};
  try {
    resolve_run_options(suite, RunFlags{});
    ADD_FAILURE() << "no error";
  } catch (const InvalidInputError& e) {
    EXPECT_NE(std::string(e.what()).find("suite unusual: field \"meshes[1]\""), std::string::npos)
        << e.what();
  }
  // The kicad suite names the folder scripts/fetch_kicad_subset.sh fills.
  const Suite kicad = load_suite("kicad", kSuitesDir);
  EXPECT_EQ(kicad.meshes, std::vector<std::filesystem::path>{"build/kicad-step"});
  EXPECT_FALSE(kicad.include_cad);
}

// --mesh and --brep-deflection describe the user's files.
TEST(ResolveRunOptions, MeshesAndTessellationComeFromTheFlags) {
  RunFlags flags;
  flags.user_meshes = {"part.step"};
  flags.brep_tessellation.linear_deflection_rel_diag = 0.01;
  const RunOptions options = resolve_run_options(unusual_suite(), flags);
  EXPECT_EQ(options.suite.meshes, std::vector<std::filesystem::path>{"part.step"});
  EXPECT_EQ(options.prepare.tessellation.linear_deflection_rel_diag, 0.01);
}

// Which suite a run starts from: --suite; else the default suite unless --case is given;
// else the built-in defaults, named "ad hoc" in the results' context.
TEST(ResolveRunOptions, TheSuiteARunStartsFrom) {
  RunFlags flags;
  EXPECT_EQ(suite_of_run_flags(flags, kSuitesDir).name, "default");
  flags.suite = "smoke";
  EXPECT_EQ(suite_of_run_flags(flags, kSuitesDir).name, "smoke");
  flags.case_patterns = {"box/*"};
  EXPECT_EQ(suite_of_run_flags(flags, kSuitesDir).name, "smoke");
  flags.suite.clear();
  const Suite ad_hoc = suite_of_run_flags(flags, kSuitesDir);
  EXPECT_EQ(ad_hoc.name, "ad hoc");

  // An ad hoc run is the built-in RunOptions with the flags given.
  const RunOptions options = resolve_run_options(ad_hoc, flags);
  const RunOptions built_in;
  EXPECT_EQ(options.suite.name, built_in.suite.name);
  EXPECT_EQ(options.suite.case_patterns, std::vector<std::string>{"box/*"});
  EXPECT_EQ(options.suite.methods, built_in.suite.methods);
  EXPECT_TRUE(options.suite.external_methods.empty());
  EXPECT_EQ(options.suite.users, built_in.suite.users);
  EXPECT_EQ(options.suite.noise_levels, built_in.suite.noise_levels);
  EXPECT_EQ(options.suite.seeds, built_in.suite.seeds);
  EXPECT_EQ(options.suite.include_cad, built_in.suite.include_cad);
  EXPECT_EQ(options.cad_data_dir, built_in.cad_data_dir);
  EXPECT_EQ(options.suite.timeout_seconds, built_in.suite.timeout_seconds);
  EXPECT_EQ(options.suite.memory_limit_bytes, built_in.suite.memory_limit_bytes);
  EXPECT_EQ(options.suite.method_repetitions, built_in.suite.method_repetitions);
  EXPECT_EQ(options.suite.evaluation.hausdorff_error_bound_rel_diag,
            built_in.suite.evaluation.hausdorff_error_bound_rel_diag);
}

}  // namespace
}  // namespace holebench::harness
