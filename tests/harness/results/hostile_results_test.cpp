// Results files that a damaged disk, a hand edit or another program could produce: each is
// refused by the reader (what merge, compare, report, history and figures read) with one line
// that names the file and the field, never accepted with a silent default and never a crash.
#include "core/errors.h"
#include "harness/results/results_reader.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace holebench::harness {
namespace {

const char* kContext = R"("context": {"schema_version": 1, "suite": "smoke"})";

// A record as holebench writes it, with `extra` fields spliced in (or replacing them: JSON
// readers keep the last of two equal keys, so `extra` comes last).
std::string record(const std::string& extra = "") {
  return R"({"job_id": "box/corner|liepa_cgal|no_user|0|0", "case_id": "box/corner",)"
         R"( "method": "liepa_cgal", "seed": 0, "noise_percent": 0, "user": "no_user",)"
         R"( "status": "ok", "metrics": {"hausdorff_rel_diag": 0.01}, "holes": [])" +
         (extra.empty() ? "" : ", " + extra) + "}";
}

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto dir = std::filesystem::temp_directory_path() / "holebench_hostile_results";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

// Reading `text` (as file `name`) throws InvalidInputError, one line, naming the file and
// every one of `named`.
void expect_refused(const std::string& name, const std::string& text,
                    const std::vector<std::string>& named) {
  SCOPED_TRACE(name);
  const auto path = write_file(name, text);
  try {
    read_results_json(path);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const InvalidInputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    EXPECT_NE(what.find(path.string()), std::string::npos) << what;
    for (const auto& word : named)
      EXPECT_NE(what.find(word), std::string::npos) << word << " not in: " << what;
  }
}

std::string results(const std::string& records) {
  return std::string("{") + kContext + R"(, "results": [)" + records + "]}";
}

TEST(HostileResults, TheWellFormedFileReads) {
  const auto data = read_results_json(write_file("good.json", results(record())));
  ASSERT_EQ(data.records.size(), 1u);
  EXPECT_EQ(data.records[0].metrics.size(), 1u);
}

// JSON has no NaN: a writer that prints one makes a file no JSON reader accepts. The error
// names the metric being read and its place in the file.
TEST(HostileResults, ANanIsRefusedNamingTheMetric) {
  expect_refused("nan.json", results(record() + ", " + record(R"("metrics": {"rms": NaN})")),
                 {"results[1].metrics.rms", "line 1"});
}

TEST(HostileResults, ANumberBeyondADoubleIsRefusedNamingTheField) {
  expect_refused("huge.json", results(record(R"("noise_percent": 1e400)")),
                 {"results[0].noise_percent", "overflow"});
}

TEST(HostileResults, AnIntegerBeyondItsTypeIsRefusedNamingTheField) {
  expect_refused("huge_seed.json", results(record(R"("seed": 1e30)")), {"record 0", "\"seed\""});
  expect_refused("huge_loop.json",
                 results(record(R"("holes": [{"hole_index": 0, "loop_size": -4}])")),
                 {"holes[0].loop_size"});
  expect_refused("huge_index.json", results(record(R"("holes": [{"hole_index": 99999999999}])")),
                 {"holes[0].hole_index"});
  expect_refused("huge_interventions.json", results(record(R"("user_interventions": 1e12)")),
                 {"user_interventions"});
}

TEST(HostileResults, AFieldOfTheWrongTypeIsRefusedNamingIt) {
  expect_refused("string_noise.json", results(record(R"("noise_percent": "five")")),
                 {"noise_percent", "expected a number"});
  expect_refused("number_case.json", results(record(R"("case_id": 7)")), {"case_id"});
  expect_refused("centroid.json", results(record(R"("holes": [{"centroid": [0, "x", 0]}])")),
                 {"holes[0].centroid[1]"});
  expect_refused("record_string.json", results("\"a record\""), {"record 0", "not a JSON object"});
}

TEST(HostileResults, AMissingFieldIsRefusedNamingIt) {
  expect_refused("no_case.json",
                 results(R"({"job_id": "x", "method": "liepa_cgal", "status": "ok"})"),
                 {"record 0", "\"case_id\" is missing"});
  expect_refused("no_results.json", std::string("{") + kContext + "}", {"\"results\""});
}

TEST(HostileResults, ADuplicateJobIdIsRefusedNamingBothRecords) {
  expect_refused("duplicate.json", results(record() + ", " + record()),
                 {"record 1", "job_id", "record 0"});
}

TEST(HostileResults, AnotherSchemaVersionIsRefused) {
  expect_refused("schema.json", R"({"context": {"schema_version": 2}, "results": []})",
                 {"context.schema_version", "2"});
  expect_refused("schema_string.json", R"({"context": {"schema_version": "1"}, "results": []})",
                 {"context.schema_version"});
}

TEST(HostileResults, AnUnknownStatusIsRefusedNamingIt) {
  expect_refused("status.json", results(record(R"("status": "fine")")), {"status", "fine"});
}

TEST(HostileResults, AFileCutShortIsRefused) {
  const std::string whole = results(record());
  expect_refused("cut.json", whole.substr(0, whole.size() / 2), {"not a JSON results file"});
}

}  // namespace
}  // namespace holebench::harness
