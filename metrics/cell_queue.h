// The queue and the loop of the branch-and-bound searches over triangle cells
// (triangle_cell.h): the cell with the largest priority is refined first (the Hausdorff
// search's priority is a cell's upper bound, the mean search's its share of the error), ties
// going to the cell created first, so the same inputs refine the same cells in the same order
// on every run. The searches derive their cells from TriangleCell to add their own bounds.
#pragma once

#include "metrics/triangle_cell.h"

#include <cstddef>
#include <queue>
#include <utility>
#include <vector>

namespace holebench {

/// The queue's order, as std::priority_queue wants it (x before y when x pops later): the
/// larger priority pops first, and of equal priorities the earlier created.
struct LargerPriorityFirst {
  bool operator()(const TriangleCell& x, const TriangleCell& y) const {
    if (x.priority != y.priority)
      return x.priority < y.priority;
    return x.order > y.order;
  }
};

/// Cells by LargerPriorityFirst; the queue stamps each cell's creation order as it takes it.
template <class Cell>
class CellQueue {
 public:
  /// Queues the first cells all at once (one heap build, no copies), their creation order
  /// the order given: the same queue as pushing them one by one, since the order is total.
  /// Call it on an empty queue.
  void start(std::vector<Cell> cells) {
    for (Cell& cell : cells)
      cell.order = next_order_++;
    heap_ = Heap(LargerPriorityFirst{}, std::move(cells));
  }

  void push(Cell cell) {
    cell.order = next_order_++;
    heap_.push(std::move(cell));
  }

  bool empty() const { return heap_.empty(); }
  const Cell& top() const { return heap_.top(); }
  void pop() { heap_.pop(); }

 private:
  using Heap = std::priority_queue<Cell, std::vector<Cell>, LargerPriorityFirst>;
  Heap heap_;
  std::size_t next_order_ = 0;
};

/// The search's loop: while the queue holds a cell and `bound_met(top cell)` is false, the
/// top cell is taken off and handed to `refine`, which queues what it makes of it (its
/// children, or itself with tighter bounds). `out_of_work()` is asked before each cell is
/// taken; once it says true the loop stops and returns false (the bound was not met).
template <class Cell, class BoundMet, class OutOfWork, class Refine>
bool refine_largest_first(CellQueue<Cell>& queue, BoundMet&& bound_met, OutOfWork&& out_of_work,
                          Refine&& refine) {
  while (!queue.empty() && !bound_met(queue.top())) {
    if (out_of_work())
      return false;
    Cell cell = queue.top();
    queue.pop();
    refine(cell);
  }
  return true;
}

}  // namespace holebench
