// The invariants every hole-filling method's test checks on its result, written once.
#pragma once

#include "core/boundary_loops.h"
#include "core/mesh.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench::test {

/// Every input face is in `repaired` with the same index, the same corners (indices) at the
/// same positions (bit for bit) and the same region, and is not new; every other face is new.
inline void expect_input_faces_unchanged(const Mesh& input, const Mesh& repaired) {
  for (auto f : input.faces()) {
    const FaceHandle g = repaired.face_handle(f.idx());
    EXPECT_FALSE(is_new(repaired, g));
    EXPECT_EQ(region(repaired, g), region(input, f));
    auto corner = repaired.cfv_begin(g);
    for (auto v : input.fv_range(f)) {
      EXPECT_EQ(corner->idx(), v.idx());
      EXPECT_EQ(repaired.point(*corner), input.point(v));
      ++corner;
    }
  }
  EXPECT_EQ(count_new_faces(repaired), repaired.n_faces() - input.n_faces());
}

/// A closed 2-manifold: no boundary loop, every edge with two faces, every vertex one fan.
inline void expect_closed_manifold(const Mesh& repaired) {
  EXPECT_TRUE(find_boundary_loops(repaired).empty());
  for (auto e : repaired.edges())
    EXPECT_FALSE(repaired.is_boundary(e));
  for (auto v : repaired.vertices())
    EXPECT_TRUE(repaired.is_manifold(v));
}

/// A test name from a case id: "box/corner" -> "box_corner".
inline std::string case_test_name(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param;
  for (char& ch : name) {
    if (ch == '/')
      ch = '_';
  }
  return name;
}

}  // namespace holebench::test
