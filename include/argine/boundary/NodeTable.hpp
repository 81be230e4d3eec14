#pragma once
/// @file NodeTable.hpp
/// A value per mesh node for the nodes a host loop touches, kept between calls so that a
/// loop run every step (HydraulicConditions::plan) allocates nothing once the tables have
/// grown to the boundary's size. It behaves as the std::map<int, T> it replaces where that
/// matters for the results: operator[] value-initialises a node's entry on its first touch
/// (so sums accumulate in the order of the touches, the same bits as the map), emplace()
/// keeps the first value, and sortedNodes() gives the nodes in increasing order.

#include <algorithm>
#include <vector>

namespace argine {

template <class T>
class NodeTable {
 public:
  /// Forgets every entry; keeps the storage.
  void clear() {
    for (const int node : nodes_) slot_[node] = -1;
    nodes_.clear();
    values_.clear();
    sorted_.clear();
  }

  /// The node's entry, value-initialised (T{}) on the node's first touch.
  T& operator[](int node) {
    int& s = slotOf(node);
    if (s < 0) {
      s = static_cast<int>(values_.size());
      nodes_.push_back(node);
      values_.push_back(T{});
    }
    return values_[s];
  }

  /// Sets the node's entry to `value` unless it has one; whether it was set.
  bool emplace(int node, const T& value) {
    if (contains(node)) return false;
    (*this)[node] = value;
    return true;
  }

  bool contains(int node) const {
    return node >= 0 && node < static_cast<int>(slot_.size()) && slot_[node] >= 0;
  }
  /// The node's entry; the node must be contained.
  const T& at(int node) const { return values_[slot_[node]]; }
  std::size_t size() const { return nodes_.size(); }

  /// The nodes with an entry, in the order of their first touch.
  const std::vector<int>& nodes() const { return nodes_; }
  /// The nodes with an entry, in increasing order (valid until the next change).
  const std::vector<int>& sortedNodes() {
    sorted_.assign(nodes_.begin(), nodes_.end());
    std::sort(sorted_.begin(), sorted_.end());
    return sorted_;
  }

 private:
  int& slotOf(int node) {
    if (node >= static_cast<int>(slot_.size())) slot_.resize(node + 1, -1);
    return slot_[node];
  }

  std::vector<int> slot_;    ///< per mesh node: its index in values_, -1 for none
  std::vector<int> nodes_;   ///< the nodes with an entry, in order of first touch
  std::vector<T> values_;    ///< their entries, in the same order
  std::vector<int> sorted_;  ///< sortedNodes()' storage
};

}  // namespace argine
