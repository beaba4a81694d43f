// The queue and the loop of the branch-and-bound searches over triangle cells
// (triangle_cell.h): the cell with the largest priority is refined first (the Hausdorff
// search's priority is a cell's upper bound, the mean search's its share of the error), ties
// going to the cell created first, so the same inputs refine the same cells in the same order
// on every run. The searches derive their cells from TriangleCell to add their own bounds.
#pragma once

#include "metrics/triangle_cell.h"

#include <algorithm>
#include <cstddef>
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
/// The heap holds each cell's priority, order and slot, the cells stay in their slots (a cell
/// is some 200 bytes, a key 24): the same comparisons in the same sequence as a heap of the
/// cells themselves, so the same cells pop in the same order, with less moved per step.
template <class Cell>
class CellQueue {
 public:
  /// Queues the first cells all at once (one heap build, no copies), their creation order
  /// the order given: the same queue as pushing them one by one, since the order is total.
  /// Call it on an empty queue.
  void start(std::vector<Cell> cells) {
    cells_ = std::move(cells);
    heap_.reserve(cells_.size());
    for (std::size_t slot = 0; slot < cells_.size(); ++slot) {
      cells_[slot].order = next_order_++;
      heap_.push_back({cells_[slot].priority, cells_[slot].order, slot});
    }
    std::make_heap(heap_.begin(), heap_.end(), KeyOrder{});
  }

  void push(Cell cell) {
    cell.order = next_order_++;
    std::size_t slot = cells_.size();
    if (free_slots_.empty()) {
      cells_.push_back(std::move(cell));
    } else {
      slot = free_slots_.back();
      free_slots_.pop_back();
      cells_[slot] = std::move(cell);
    }
    heap_.push_back({cells_[slot].priority, cells_[slot].order, slot});
    std::push_heap(heap_.begin(), heap_.end(), KeyOrder{});
  }

  bool empty() const { return heap_.empty(); }
  const Cell& top() const { return cells_[heap_.front().slot]; }
  void pop() {
    free_slots_.push_back(heap_.front().slot);
    std::pop_heap(heap_.begin(), heap_.end(), KeyOrder{});
    heap_.pop_back();
  }

 private:
  struct Key {
    double priority = 0.0;
    std::size_t order = 0;
    std::size_t slot = 0;
  };
  /// LargerPriorityFirst on the keys.
  struct KeyOrder {
    bool operator()(const Key& x, const Key& y) const {
      if (x.priority != y.priority)
        return x.priority < y.priority;
      return x.order > y.order;
    }
  };
  std::vector<Cell> cells_;              ///< queued cells and free slots
  std::vector<std::size_t> free_slots_;  ///< slots of popped cells, reused by push()
  std::vector<Key> heap_;
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
