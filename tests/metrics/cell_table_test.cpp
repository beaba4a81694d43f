// Invariant: a CellTable gives, for a key, the value first added with it, whether the cell is
// looked up at its own face, at another face (whose entry has another key) or at none, and
// nothing for a key never added.
#include "metrics/cell_table.h"

#include <gtest/gtest.h>

#include <string>

namespace holebench {
namespace {

// A cell whose key differs from the others' by `n` (in its first corner and its faces).
CellKey key_number(int n) {
  TriangleCell cell;
  cell.corners = {Point(n, 0.5 * n, 0.0), Point(1.0, 0.0, 0.0), Point(0.0, 1.0, 0.0)};
  cell.corner_distance = {0.1 * n, 0.2, 0.3};
  cell.corner_face = {n, n + 1, n + 2};
  return key_of(cell);
}

TEST(CellTable, FindsTheValueOfAKeyAtItsFaceAtAnotherOrAtNone) {
  CellTable<std::string> table;
  table.reserve(8);
  for (int face = 0; face < 8; face += 2)  // faces 0, 2, 4, 6: keys 0, 2, 4, 6
    table.add(face, key_number(face), "value " + std::to_string(face));
  EXPECT_EQ(table.size(), 4u);
  for (int face = 0; face < 8; face += 2) {
    const std::string expected = "value " + std::to_string(face);
    for (int at : {face, (face + 2) % 8, 1, 7, 100, -1}) {
      const std::string* found = table.find(key_number(face), at);
      ASSERT_NE(found, nullptr) << face << " at " << at;
      EXPECT_EQ(*found, expected) << face << " at " << at;
    }
  }
  for (int missing : {1, 3, 9})
    for (int at : {0, missing, -1})
      EXPECT_EQ(table.find(key_number(missing), at), nullptr) << missing << " at " << at;
}

TEST(CellTable, ASecondFaceWithAKeyAlreadyAddedFindsTheFirstValue) {
  CellTable<int> table;
  table.add(3, key_number(5), 30);
  table.add(1, key_number(5), 10);  // the same cell on another face: the first value stays
  table.add(2, key_number(6), 20);
  table.add(-1, key_number(7), 70);  // a cell of no face: found by its key alone
  EXPECT_EQ(table.size(), 3u);
  ASSERT_NE(table.find(key_number(7), -1), nullptr);
  EXPECT_EQ(*table.find(key_number(7), 2), 70);
  for (int at : {1, 2, 3, -1}) {
    ASSERT_NE(table.find(key_number(5), at), nullptr) << at;
    EXPECT_EQ(*table.find(key_number(5), at), 30) << at;
  }
  EXPECT_EQ(*table.find(key_number(6), 2), 20);
}

}  // namespace
}  // namespace holebench
