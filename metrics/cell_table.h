// What a search computed once per case for the first cells of a mesh A0 (a value per face's
// cell: MeanCellBounds, HausdorffCellBounds), looked up by cell (CellKey) for the cells of
// another mesh A. Most lookups are of A0's own face at the same index (the complete model's
// faces in every job; a repair that appends to the input keeps each input face at its index),
// so the table first tries that face's entry, read in face order, and compares the keys;
// only a cell that is not its face's goes through the hash of its key. The answer is the
// same either way: the value of the first face added with that key.
#pragma once

#include "metrics/triangle_cell.h"

#include <cstddef>
#include <unordered_map>
#include <vector>

namespace holebench {

template <class Value>
class CellTable {
 public:
  /// Room for the cells of a mesh of `faces` faces.
  void reserve(std::size_t faces) {
    keys_.reserve(faces);
    values_.reserve(faces);
    entry_of_face_.reserve(faces);
    entry_of_key_.reserve(faces);
  }

  /// The value of the cell of A0's face `face` (each face at most once); a key added before
  /// keeps its first value.
  void add(int face, const CellKey& key, Value value) {
    const auto [it, added] = entry_of_key_.emplace(key, static_cast<int>(keys_.size()));
    if (face >= 0) {
      if (static_cast<std::size_t>(face) >= entry_of_face_.size())
        entry_of_face_.resize(static_cast<std::size_t>(face) + 1, -1);
      entry_of_face_[static_cast<std::size_t>(face)] = it->second;
    }
    if (added) {
      keys_.push_back(key);
      values_.push_back(std::move(value));
    }
  }

  /// The value of the cell with `key`, or null; `face`: the face of A0 whose cell it may be
  /// (tried first), or -1.
  const Value* find(const CellKey& key, int face) const {
    if (face >= 0 && static_cast<std::size_t>(face) < entry_of_face_.size()) {
      const int entry = entry_of_face_[static_cast<std::size_t>(face)];
      if (entry >= 0 && keys_[static_cast<std::size_t>(entry)] == key)
        return &values_[static_cast<std::size_t>(entry)];
    }
    const auto it = entry_of_key_.find(key);
    return it == entry_of_key_.end() ? nullptr : &values_[static_cast<std::size_t>(it->second)];
  }

  std::size_t size() const { return keys_.size(); }  ///< cells held (distinct keys)

 private:
  std::vector<CellKey> keys_;
  std::vector<Value> values_;
  std::vector<int> entry_of_face_;  // by face of A0: its entry, or -1
  std::unordered_map<CellKey, int, CellKeyHash> entry_of_key_;
};

}  // namespace holebench
