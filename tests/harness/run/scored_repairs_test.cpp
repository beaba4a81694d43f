// Repairs scored from files (`run --repaired-meshes`, `evaluate --cases`): a run's repairs,
// written and scored again against the cases' exports, give the run's records (every metric
// but the times, to 1e-12 relative); a missing repaired mesh, one that drops an input face, and an
// export that is not the case are recorded as failures with their reason.
#include "harness/run/scored_repairs.h"
#include "core/mesh_io.h"
#include "generators/case_catalog.h"
#include "harness/outputs/case_export.h"
#include "harness/outputs/file_names.h"
#include "harness/run/exported_cases.h"
#include "harness/run/run_jobs.h"
#include "tests/harness/record_lookup.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace holebench::harness {
namespace {

namespace fs = std::filesystem;
using test_support::metric;

fs::path fresh_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("holebench_test_" + name);
  fs::remove_all(dir);
  return dir;
}

const std::vector<std::string> kCases = {"box/corner", "brep/k2/inner/convex/small"};

RunOptions quiet_run(const fs::path& out) {
  RunOptions options;
  options.out_dir = out;
  options.suite.case_patterns = kCases;
  options.suite.include_cad = false;
  options.snapshots = false;
  options.progress = false;
  options.in_process = true;
  return options;
}

// The cases of kCases exported at each noise level, one folder per level.
fs::path export_cases(const fs::path& root, const std::vector<double>& noise_levels) {
  generators::CatalogOptions catalog_options;
  catalog_options.include_cad = false;
  const generators::CaseCatalog catalog(catalog_options);
  for (const double noise : noise_levels) {
    for (const auto& id : kCases)
      export_case(
          catalog.make(id, 0, noise),
          root / ("noise-" + std::to_string(static_cast<int>(noise))) / file_stem_of_id(id));
  }
  return root;
}

// The run that scores `method`'s repairs in `repaired` against the exports under `cases`.
RunSummary score(const fs::path& cases, const fs::path& repaired, const std::string& method,
                 const fs::path& out, const std::string& user = "no_user") {
  RunOptions options = quiet_run(out);
  ScoredRepairs scored;
  scored.repaired_dir = repaired;
  for (const auto& exported : find_exported_cases({cases})) {
    Job job = scoring_job(exported, method, user);
    scored.exported_inputs[job.case_instance()] = exported.input;
    options.jobs.push_back(job);
  }
  options.scored_repairs = scored;
  return run_jobs(options);
}

std::map<std::string, JobRecord> by_id(const std::vector<JobRecord>& records) {
  std::map<std::string, JobRecord> map;
  for (const auto& record : records)
    map[record.job.id()] = record;
  return map;
}

TEST(ScoredRepairs, ARunsRepairsScoredAgainGiveItsRecords) {
  RunOptions run = quiet_run(fresh_dir("scored_run"));
  run.suite.methods = {"liepa_cgal", "cgal_triangulate"};
  run.suite.noise_levels = {0.0, 5.0};
  run.repaired_meshes = true;
  const RunSummary made = run_jobs(run);
  ASSERT_EQ(made.records.size(), 8u);
  const fs::path cases = export_cases(fresh_dir("scored_cases"), {0.0, 5.0});
  for (const std::string method : {"liepa_cgal", "cgal_triangulate"}) {
    SCOPED_TRACE(method);
    const RunSummary scored =
        score(cases, run.out_dir / "repaired", method, fresh_dir("scored_" + method));
    ASSERT_EQ(scored.records.size(), 4u);
    const auto made_by_id = by_id(made.records);
    for (const auto& record : scored.records) {
      SCOPED_TRACE(record.job.id());
      ASSERT_EQ(made_by_id.count(record.job.id()), 1u);
      const JobRecord& original = made_by_id.at(record.job.id());
      EXPECT_EQ(record.status, original.status) << record.message;
      EXPECT_EQ(record.message, original.message);
      EXPECT_EQ(record.case_family, original.case_family);
      EXPECT_EQ(record.holes.size(), original.holes.size());
      EXPECT_EQ(record.job.method_options.values().size(),
                original.job.method_options.values().size());
      EXPECT_EQ(record.method_seconds, original.method_seconds);
      ASSERT_EQ(record.metrics.size(), original.metrics.size());
      for (std::size_t i = 0; i < record.metrics.size(); ++i) {
        EXPECT_EQ(record.metrics[i].name, original.metrics[i].name);
        // The patch's edges and new vertices are numbered as the file lists them, not as the
        // method made them: a sum over them may run in another order (its last bits).
        const double a = record.metrics[i].value, b = original.metrics[i].value;
        EXPECT_LE(std::abs(a - b), 1e-12 * std::max(std::abs(a), std::abs(b)))
            << record.metrics[i].name << ": " << a << " against " << b;
      }
    }
  }
}

// Repairs made elsewhere: one mesh per exported case, named after the case, no side file.
TEST(ScoredRepairs, ARepairNamedAfterItsCaseIsScoredFromItsMeshAlone) {
  RunOptions run = quiet_run(fresh_dir("scored_plain_run"));
  run.suite.methods = {"liepa_cgal"};
  run.repaired_meshes = true;
  const RunSummary made = run_jobs(run);
  const fs::path cases = export_cases(fresh_dir("scored_plain_cases"), {0.0});
  const fs::path elsewhere = fresh_dir("scored_plain_meshes");
  fs::create_directories(elsewhere);
  for (const auto& record : made.records) {
    // Written as another program would: OFF text, no side file.
    write_mesh(read_mesh(run.out_dir / "repaired" / (file_stem_of_id(record.job.id()) + ".ply")),
               elsewhere / (file_stem_of_id(record.job.case_id) + ".off"));
  }
  // Scored as the oracle user's jobs: with no side file, the record names the job's user.
  const RunSummary scored = score(cases, elsewhere, "my_fill", fresh_dir("scored_plain"), "oracle");
  const auto made_by_case = [&](const std::string& case_id) {
    for (const auto& record : made.records)
      if (record.job.case_id == case_id)
        return record;
    return JobRecord{};
  };
  ASSERT_EQ(scored.records.size(), 2u);
  for (const auto& record : scored.records) {
    SCOPED_TRACE(record.job.id());
    EXPECT_EQ(record.job.method_id, "my_fill");
    EXPECT_EQ(record.job.user, "oracle");
    EXPECT_EQ(record.user, "oracle");
    EXPECT_EQ(record.status, JobStatus::Ok) << record.message;
    ASSERT_FALSE(record.holes.empty());
    for (const auto& hole : record.holes)
      EXPECT_TRUE(hole.closed);
    const JobRecord original = made_by_case(record.job.case_id);
    for (const char* name : {"hausdorff_rel_diag", "hole_hausdorff_rel_diag", "is_closed",
                             "new_faces_count", "self_intersections_count"})
      EXPECT_EQ(metric(record, name), metric(original, name)) << name;
  }
}

TEST(ScoredRepairs, AMissingOrBrokenRepairIsAFailedRecordWithItsReason) {
  const fs::path cases = export_cases(fresh_dir("scored_missing_cases"), {0.0});
  const fs::path meshes = fresh_dir("scored_missing_meshes");
  fs::create_directories(meshes);
  // box/corner: the holed mesh with one more face dropped; the other case: nothing.
  generators::CatalogOptions catalog_options;
  catalog_options.include_cad = false;
  const Case corner = generators::CaseCatalog(catalog_options).make("box/corner");
  TriangleSoup dropped = to_soup(corner.input);
  dropped.triangles.pop_back();
  dropped.regions.clear();
  write_mesh(build_mesh(dropped), meshes / "box_corner.ply");
  const RunSummary scored = score(cases, meshes, "my_fill", fresh_dir("scored_missing"));
  ASSERT_EQ(scored.records.size(), 2u);
  for (const auto& record : scored.records) {
    SCOPED_TRACE(record.job.id());
    EXPECT_EQ(record.status, JobStatus::MethodFailed);
    if (record.job.case_id == "box/corner")
      EXPECT_NE(record.message.find("changed or dropped 1 of the input's"), std::string::npos)
          << record.message;
    else
      EXPECT_NE(record.message.find("no repaired mesh for this job"), std::string::npos)
          << record.message;
    EXPECT_TRUE(record.metrics.empty());
  }
}

TEST(ScoredRepairs, AnExportThatIsNotTheCaseIsInvalidInput) {
  const fs::path cases = export_cases(fresh_dir("scored_other_cases"), {0.0});
  // The corner's export replaced by another case's holed mesh.
  generators::CatalogOptions catalog_options;
  catalog_options.include_cad = false;
  const Case edge = generators::CaseCatalog(catalog_options).make("box/edge");
  write_mesh(edge.input, cases / "noise-0" / "box_corner" / "input.ply");
  const RunSummary scored =
      score(cases, fresh_dir("scored_other_meshes"), "my_fill", fresh_dir("scored_other"));
  int corner_records = 0;
  for (const auto& record : scored.records) {
    SCOPED_TRACE(record.job.id());
    if (record.job.case_id == "box/corner") {
      ++corner_records;
      EXPECT_EQ(record.status, JobStatus::InvalidInput);
      EXPECT_NE(record.message.find("is not the case made again"), std::string::npos)
          << record.message;
    }
  }
  EXPECT_EQ(corner_records, 1);  // the loop above checked the replaced export
}

TEST(ScoredRepairs, TheNamingRuleTriesTheJobThenTheCase) {
  const Job job{"brep/k2/inner/convex/small", "liepa_cgal", 5.0, 0, "no_user"};
  const auto candidates = repaired_mesh_candidates("out", job);
  ASSERT_EQ(candidates.size(), 8u);
  EXPECT_EQ(candidates[0], fs::path("out") / (file_stem_of_id(job.id()) + ".ply"));
  EXPECT_EQ(candidates[4], fs::path("out/brep_k2_inner_convex_small.ply"));
  EXPECT_EQ(candidates[7], fs::path("out/brep_k2_inner_convex_small.stl"));
  EXPECT_EQ(method_record_path("out/a_b.ply"), fs::path("out/a_b.method.json"));
}

}  // namespace
}  // namespace holebench::harness
