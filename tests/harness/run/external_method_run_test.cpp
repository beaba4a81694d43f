// External methods through the runner: the worked example (examples/fan_fill.py) end to end
// in isolated job processes, the record naming its command, a program stopped with its job at
// the time limit, the plan's rules for naming external methods, suites and the command line.
#include "core/errors.h"
#include "harness/results/record_json.h"
#include "harness/results/results_reader.h"
#include "harness/results/validate_results.h"
#include "harness/run/run_jobs.h"
#include "harness/run/suite.h"
#include "tests/harness/record_lookup.h"

#include <gtest/gtest.h>
#include <signal.h>

#include <filesystem>
#include <fstream>

namespace holebench::harness {
namespace {

using test_support::metric;

std::filesystem::path fresh_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("holebench_test_" + name);
  std::filesystem::remove_all(dir);
  return dir;
}

const std::string kFanFill =
    "python3 '" + std::string(HOLEBENCH_SOURCE_DIR) + "/examples/fan_fill.py' {input} {output}";

RunOptions fan_fill_run(const std::string& folder) {
  RunOptions options;
  options.out_dir = fresh_dir(folder);
  options.suite.case_patterns = {"box/face_interior", "box/corner"};
  options.suite.methods = {"fan_fill"};
  options.suite.external_methods = {{"fan_fill", kFanFill, 0.0, {}}};
  options.suite.include_cad = false;
  options.snapshots = false;
  options.progress = false;
  options.workers = 1;
  return options;
}

// The worked example as an external method, each job in its own process: ok, closed, the
// input's faces unchanged, and the record (in results.json too) names the command.
TEST(ExternalMethodRun, TheFanFillExampleRunsEndToEnd) {
  const RunOptions options = fan_fill_run("external_fan_fill");
  const RunSummary summary = run_jobs(options);
  ASSERT_EQ(summary.records.size(), 2u);
  for (const auto& record : summary.records) {
    SCOPED_TRACE(record.job.id());
    EXPECT_EQ(record.job.method_id, "fan_fill");
    EXPECT_EQ(record.status, JobStatus::Ok) << record.message;
    EXPECT_EQ(metric(record, "is_closed"), 1.0);
    EXPECT_EQ(metric(record, "is_manifold"), 1.0);
    EXPECT_EQ(metric(record, "original_faces_unchanged_ok"), 1.0);
    EXPECT_EQ(metric(record, "open_boundary_loops_count"), 0.0);
    ASSERT_EQ(record.holes.size(), 1u);
    EXPECT_TRUE(record.holes[0].closed);
    EXPECT_EQ(record.holes[0].new_faces, record.holes[0].loop_size);
    EXPECT_GT(record.method_seconds, 0.0);
  }
  const ResultsData data = read_results_json(summary.results_json);
  ASSERT_EQ(data.records.size(), 2u);
  ASSERT_TRUE(data.records[0].job.external.has_value());
  EXPECT_EQ(data.records[0].job.external->command, kFanFill);
  EXPECT_TRUE(validate_results_files({summary.results_json}).ok());
}

// A program past the job's time limit is stopped with its job (the job's process group).
TEST(ExternalMethodRun, AProgramPastTheTimeLimitIsStoppedWithItsJob) {
  RunOptions options = fan_fill_run("external_timeout");
  options.suite.case_patterns = {"box/corner"};
  const auto pid_file = options.out_dir.parent_path() / "holebench_test_external_timeout.pid";
  const auto dir_file = options.out_dir.parent_path() / "holebench_test_external_timeout.dir";
  std::filesystem::remove(pid_file);
  options.suite.external_methods = {{"fan_fill",
                                     "dirname {input} > '" + dir_file.string() + "'; echo $$ > '" +
                                         pid_file.string() + "'; exec sleep 60; : {output}",
                                     0.0,
                                     {}}};
  options.suite.timeout_seconds = 2.0;
  const RunSummary summary = run_jobs(options);
  ASSERT_EQ(summary.records.size(), 1u);
  EXPECT_EQ(summary.records[0].status, JobStatus::Timeout);
  ASSERT_TRUE(summary.records[0].job.external.has_value());  // a timeout record names it too
  std::ifstream in(pid_file);
  pid_t pid = 0;
  ASSERT_TRUE(in >> pid);
  // The program was killed with the job; only its zombie entry may linger for a moment.
  bool gone = false;
  for (int i = 0; i < 100 && !gone; ++i) {
    gone = ::kill(pid, 0) != 0;
    if (!gone) {
      std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
      std::string skip, state;
      stat >> skip >> skip >> state;
      gone = state == "Z";
    }
    if (!gone)
      ::usleep(20000);
  }
  EXPECT_TRUE(gone) << "the program (pid " << pid << ") outlived its job";
  // Its temporary files went with the job's temporary folder.
  std::string input_dir;
  std::ifstream dir_in(dir_file);
  ASSERT_TRUE(std::getline(dir_in, input_dir));
  EXPECT_FALSE(input_dir.empty());
  EXPECT_FALSE(std::filesystem::exists(input_dir)) << input_dir;
}

TEST(ExternalMethodRun, ThePlanAddsExternalMethodsAndChecksTheirNames) {
  RunOptions options = fan_fill_run("external_plan");
  options.suite.include_cad = false;
  const generators::CaseCatalog catalog(run_catalog_options(options));
  // Named alone: only it runs.
  EXPECT_EQ(plan_jobs(options, catalog).size(), 2u);
  // Not named: it runs beside the --method ids.
  options.suite.methods = {"liepa_cgal"};
  auto jobs = plan_jobs(options, catalog);
  ASSERT_EQ(jobs.size(), 4u);
  EXPECT_EQ(jobs[1].method_id, "fan_fill");
  EXPECT_FALSE(jobs[0].external.has_value());
  ASSERT_TRUE(jobs[1].external.has_value());
  // A predefined one by name, without a definition.
  options.suite.methods = {"meshlab_close_holes"};
  options.suite.external_methods.clear();
  jobs = plan_jobs(options, catalog);
  ASSERT_EQ(jobs.size(), 2u);
  ASSERT_TRUE(jobs[0].external.has_value());
  EXPECT_NE(jobs[0].external->command.find("meshlabserver"), std::string::npos);
  // Every built-in by default; predefined external methods only by name.
  options.suite.methods.clear();
  for (const auto& job : plan_jobs(options, catalog))
    EXPECT_FALSE(job.external.has_value()) << job.id();
  // A built-in's id, or a name defined twice, is refused.
  options.suite.external_methods = {{"liepa_cgal", kFanFill, 0.0, {}}};
  EXPECT_THROW(plan_jobs(options, catalog), std::invalid_argument);
  options.suite.external_methods = {{"a", kFanFill, 0.0, {}}, {"a", kFanFill, 0.0, {}}};
  EXPECT_THROW(plan_jobs(options, catalog), std::invalid_argument);
}

TEST(ExternalMethodRun, SuitesDefineExternalMethodsOrNamePredefinedOnes) {
  const auto dir = fresh_dir("external_suite");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "with_external.json") << R"({"cases": ["box/*"], "external_methods": [
      {"name": "fan_fill", "command": "python3 fan_fill.py {input} {output}"},
      {"name": "meshlab_close_holes"}]})";
  const Suite suite = load_suite("with_external", dir);
  ASSERT_EQ(suite.external_methods.size(), 2u);
  EXPECT_EQ(suite.external_methods[0].command, "python3 fan_fill.py {input} {output}");
  EXPECT_EQ(suite.external_methods[1].name, "meshlab_close_holes");
  EXPECT_FALSE(suite.external_methods[1].required_programs.empty());
  std::ofstream(dir / "bad_placeholder.json")
      << R"({"cases": ["box/*"], "external_methods": [{"name": "x", "command": "x {in} {output}"}]})";
  EXPECT_THROW(load_suite("bad_placeholder", dir), InvalidInputError);
  std::ofstream(dir / "unknown_predefined.json")
      << R"({"cases": ["box/*"], "external_methods": [{"name": "nothing_known"}]})";
  EXPECT_THROW(load_suite("unknown_predefined", dir), InvalidInputError);
  // The paper suite runs MeshLab's Close Holes; the others do not (a process per job).
  EXPECT_EQ(load_suite("paper").external_methods.size(), 1u);
  for (const char* name : {"default", "smoke", "nightly"})
    EXPECT_TRUE(load_suite(name).external_methods.empty()) << name;
}

TEST(ExternalMethodRun, TheRecordNamesTheCommandAndReadsBack) {
  JobRecord record;
  record.job = {"box/corner", "meshlab_close_holes", 0.0, 0, "no_user"};
  record.job.external = ExternalMethodSpec{"meshlab_close_holes", "m {input} {output}", 1e-6, {}};
  const auto j = record_to_json(record);
  EXPECT_EQ(j["method_options"]["command"], "m {input} {output}");
  EXPECT_EQ(j["method_options"]["vertex_tolerance_rel_diag"], 1e-6);
  const JobRecord back = record_from_json(nlohmann::json::parse(j.dump()));
  ASSERT_TRUE(back.job.external.has_value());
  EXPECT_EQ(back.job.external->command, "m {input} {output}");
  EXPECT_EQ(back.job.external->vertex_tolerance_rel_diag, 1e-6);
  // A built-in's record has no method_options.
  record.job.external.reset();
  EXPECT_FALSE(record_to_json(record).contains("method_options"));
}

}  // namespace
}  // namespace holebench::harness
