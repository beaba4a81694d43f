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

}  // namespace
}  // namespace holebench::harness
