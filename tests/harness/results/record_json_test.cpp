#include "harness/results/record_json.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace holebench::harness {
namespace {

// A hole's fallback is written in every hole record ("" when the method's own path handled
// it) and reads back as written; a hole record of an older file without it reads as "".
TEST(RecordJson, HoleFallbackRoundTripsAndDefaultsToEmpty) {
  JobRecord r;
  r.job.case_id = "box/corner";
  r.job.method_id = "liepa_cgal";
  HoleRecord own;
  own.hole_index = 0;
  own.closed = true;
  HoleRecord stood_in;
  stood_in.hole_index = 1;
  stood_in.closed = true;
  stood_in.note = "a sub-hole could not be stitched";
  stood_in.fallback = "cgal_triangulate_hole";
  r.holes = {own, stood_in};

  const std::string line = record_to_json_line(r);
  const auto json = nlohmann::json::parse(line);
  ASSERT_TRUE(json["holes"][0].contains("fallback"));
  EXPECT_EQ(json["holes"][0]["fallback"], "");
  EXPECT_EQ(json["holes"][1]["fallback"], "cgal_triangulate_hole");

  const JobRecord back = record_from_json_text(line);
  ASSERT_EQ(back.holes.size(), 2u);
  EXPECT_EQ(back.holes[0].fallback, "");
  EXPECT_EQ(back.holes[1].fallback, "cgal_triangulate_hole");
  EXPECT_EQ(back.holes[1].note, "a sub-hole could not be stitched");

  auto older = json;
  older["holes"][1].erase("fallback");
  EXPECT_EQ(record_from_json_text(older.dump()).holes[1].fallback, "");
}

// A built-in method's settings are written as "method_options" and read back as written; a
// record of an older file without them reads with none. An external method's record keeps
// its command there instead.
TEST(RecordJson, MethodOptionsRoundTrip) {
  JobRecord r;
  r.job.case_id = "box/corner";
  r.job.method_id = "crest_feature";
  r.job.method_options.add("crest_lines.jet_degree", 3)
      .add("filling.refine_and_fair", false)
      .add("feature_points.reach_edges", 4.0)
      .add("interpolation.control_points", "tangent_line");
  const std::string line = record_to_json_line(r);
  const auto json = nlohmann::json::parse(line);
  EXPECT_EQ(json["method_options"]["crest_lines.jet_degree"], 3);
  EXPECT_EQ(json["method_options"]["interpolation.control_points"], "tangent_line");
  const JobRecord back = record_from_json_text(line);
  EXPECT_EQ(back.job.method_options, r.job.method_options);
  EXPECT_FALSE(back.job.external);

  auto older = json;
  older.erase("method_options");
  EXPECT_TRUE(record_from_json_text(older.dump()).job.method_options.empty());

  auto nested = json;
  nested["method_options"]["crest_lines"] = nlohmann::json::object();
  EXPECT_THROW(record_from_json_text(nested.dump()), std::invalid_argument);

  JobRecord external;
  external.job.case_id = "box/corner";
  external.job.method_id = "fan_fill";
  external.job.external = ExternalMethodSpec{"fan_fill", "fan {input} {output}", 0.0, {}};
  const JobRecord external_back = record_from_json_text(record_to_json_line(external));
  ASSERT_TRUE(external_back.job.external);
  EXPECT_EQ(external_back.job.external->command, "fan {input} {output}");
  EXPECT_TRUE(external_back.job.method_options.empty());
}

}  // namespace
}  // namespace holebench::harness
