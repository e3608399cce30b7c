#pragma once

#include <numeric>
#include <vector>

namespace spira {

// Disjoint sets over 0..n-1 with path halving. unite() links the larger root under the smaller,
// so a set's root is always its smallest element: callers use that to keep "first occurrence"
// order without extra bookkeeping.
class UnionFind {
 public:
  explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }

  int find(int x)
  {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  // True when a and b were in different sets.
  bool unite(int a, int b)
  {
    a = find(a);
    b = find(b);
    if (a == b) return false;
    if (a < b)
      parent_[b] = a;
    else
      parent_[a] = b;
    return true;
  }

  size_t size() const { return parent_.size(); }

 private:
  std::vector<int> parent_;
};

}  // namespace spira
