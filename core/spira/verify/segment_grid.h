#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// The deposited segments of a path in a uniform grid of cubic cells: a segment is listed in every
// cell its bounding box, grown by `margin`, overlaps. Segment k runs from points[from[k]] to
// points[from[k] + 1].
class SegmentGrid {
 public:
  SegmentGrid(const std::vector<Vec3>& points, std::vector<size_t> from, double cell, double margin);

  double cell() const { return cell_; }
  size_t size() const { return from_.size(); }
  size_t from(size_t segment) const { return from_[segment]; }
  // Appends the segments listed in the cells overlapping the box [lo, hi] to `out` (possibly
  // more than once; callers dedupe when it matters).
  void collect(const Vec3& lo, const Vec3& hi, std::vector<uint32_t>& out) const;

 private:
  int64_t key(int64_t x, int64_t y, int64_t z) const;
  double cell_;
  std::vector<size_t> from_;
  std::vector<std::pair<int64_t, uint32_t>> entries_;  // (cell key, segment), sorted by key
};

// Distance from p to segment [a, c].
double pointSegmentDistance(const Vec3& p, const Vec3& a, const Vec3& c);

}  // namespace spira
