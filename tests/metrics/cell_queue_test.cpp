// Invariant: the queue pops the larger priority first and, of equal priorities, the cell
// created first (the first cells in the order given, then later pushes); the search's loop
// stops when the bound is met or the work runs out, and says which.
#include "metrics/cell_queue.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace holebench {
namespace {

TriangleCell with_priority(double priority) {
  TriangleCell cell;
  cell.priority = priority;
  return cell;
}

// A cell that remembers which one it is.
struct NamedCell : TriangleCell {
  int name = -1;
};

NamedCell named(int name, double priority) {
  NamedCell cell;
  cell.name = name;
  cell.priority = priority;
  return cell;
}

std::vector<int> pop_all(CellQueue<NamedCell>& queue) {
  std::vector<int> names;
  while (!queue.empty()) {
    names.push_back(queue.top().name);
    queue.pop();
  }
  return names;
}

TEST(CellQueue, OrderPutsTheLargerPriorityFirstAndTiesToTheEarlierCell) {
  const LargerPriorityFirst pops_later;
  TriangleCell small = with_priority(1.0), large = with_priority(2.0);
  EXPECT_TRUE(pops_later(small, large));
  EXPECT_FALSE(pops_later(large, small));
  TriangleCell early = with_priority(1.0), late = with_priority(1.0);
  early.order = 3;
  late.order = 4;
  EXPECT_TRUE(pops_later(late, early));
  EXPECT_FALSE(pops_later(early, late));
  EXPECT_FALSE(pops_later(early, early));
}

TEST(CellQueue, PopsLargerPrioritiesFirst) {
  CellQueue<NamedCell> queue;
  queue.start({named(0, 0.5), named(1, 3.0), named(2, 1.0)});
  queue.push(named(3, 2.0));
  queue.push(named(4, 0.25));
  EXPECT_EQ(pop_all(queue), (std::vector<int>{1, 3, 2, 0, 4}));
}

TEST(CellQueue, EqualPrioritiesPopInCreationOrder) {
  CellQueue<NamedCell> queue;
  queue.start({named(0, 1.0), named(1, 1.0), named(2, 1.0)});
  queue.push(named(3, 1.0));
  queue.push(named(4, 1.0));
  EXPECT_EQ(pop_all(queue), (std::vector<int>{0, 1, 2, 3, 4}));
}

TEST(CellQueue, StampsCreationOrderFromTheFirstCellsOn) {
  CellQueue<NamedCell> queue;
  NamedCell stale = named(0, 2.0);
  stale.order = 99;  // replaced when queued
  queue.start({stale, named(1, 1.0)});
  queue.push(named(2, 0.5));
  std::vector<std::size_t> orders;
  while (!queue.empty()) {
    orders.push_back(queue.top().order);
    queue.pop();
  }
  EXPECT_EQ(orders, (std::vector<std::size_t>{0, 1, 2}));
}

// Pushes and pops interleaved, with many equal priorities, pop the cells in the order of a
// sort by priority, then creation.
TEST(CellQueue, InterleavedPushesAndPopsPopInPriorityThenCreationOrder) {
  CellQueue<NamedCell> queue;
  std::vector<NamedCell> first;
  for (int name = 0; name < 20; ++name)
    first.push_back(named(name, (name * 7) % 5));
  queue.start(first);
  // The reference: every queued cell with its creation order; the next to pop is the
  // largest by LargerPriorityFirst.
  std::vector<NamedCell> queued = first;
  for (std::size_t i = 0; i < queued.size(); ++i)
    queued[i].order = i;
  std::size_t next_order = queued.size();
  std::vector<int> popped, expected;
  int next_name = 20;
  for (int round = 0; round < 200; ++round) {
    if (round % 3 != 2) {
      NamedCell cell = named(next_name++, (round * 11) % 4);
      queue.push(cell);
      cell.order = next_order++;
      queued.push_back(cell);
    } else {
      for (int k = 0; k < 2 && !queue.empty(); ++k) {
        const auto largest = std::max_element(queued.begin(), queued.end(), LargerPriorityFirst{});
        expected.push_back(largest->name);
        queued.erase(largest);
        popped.push_back(queue.top().name);
        queue.pop();
      }
    }
  }
  while (!queue.empty()) {
    const auto largest = std::max_element(queued.begin(), queued.end(), LargerPriorityFirst{});
    expected.push_back(largest->name);
    queued.erase(largest);
    popped.push_back(queue.top().name);
    queue.pop();
  }
  EXPECT_TRUE(queued.empty());
  EXPECT_EQ(popped.size(), 20u + 134u);
  EXPECT_EQ(popped, expected);
}

// A toy search: each refined cell is replaced by two of half its priority, until the top
// priority is at most `bound`.
TEST(CellQueue, RefineLoopStopsWhenTheBoundIsMet) {
  CellQueue<NamedCell> queue;
  queue.start({named(0, 1.0)});
  int refined = 0;
  const bool met = refine_largest_first(
      queue, [](const NamedCell& top) { return top.priority <= 0.25; }, [] { return false; },
      [&](NamedCell& cell) {
        ++refined;
        queue.push(named(cell.name, 0.5 * cell.priority));
        queue.push(named(cell.name, 0.5 * cell.priority));
      });
  EXPECT_TRUE(met);
  EXPECT_EQ(refined, 1 + 2);  // 1.0, then both 0.5: four cells of 0.25 remain
  EXPECT_EQ(queue.top().priority, 0.25);
}

TEST(CellQueue, RefineLoopStopsWhenTheWorkRunsOut) {
  CellQueue<NamedCell> queue;
  queue.start({named(0, 1.0)});
  int refined = 0;
  const bool met = refine_largest_first(
      queue, [](const NamedCell&) { return false; }, [&] { return refined >= 5; },
      [&](NamedCell& cell) {
        ++refined;
        queue.push(named(cell.name, 0.5 * cell.priority));
      });
  EXPECT_FALSE(met);
  EXPECT_EQ(refined, 5);
}

TEST(CellQueue, RefineLoopEndsOnAnEmptyQueue) {
  CellQueue<NamedCell> queue;
  queue.start({named(0, 1.0), named(1, 2.0)});
  std::vector<int> order;
  const bool met = refine_largest_first(
      queue, [](const NamedCell&) { return false; }, [] { return false; },
      [&](NamedCell& cell) { order.push_back(cell.name); });
  EXPECT_TRUE(met);
  EXPECT_EQ(order, (std::vector<int>{1, 0}));
}

}  // namespace
}  // namespace holebench
