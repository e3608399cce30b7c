#pragma once

#include <optional>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira::geodesic {

// Where neighbouring generatrices touch or run together: shortest paths on a mesh bend only at
// vertices whose angles sum to more than 2 pi (the saddles of a waist, a faceted or corrugated
// wall), so paths from neighbouring base points can pass the same vertex on either side, or funnel
// through it and share the rest of their way.
struct MergedNeighbours {
  size_t pairs = 0;          // neighbouring pairs that meet
  size_t first = 0;          // the longest stretch: lines[first] and the next one (cyclically)
  double stretch = 0.0;      // its length along lines[first], mm (0: they touch at one point)
  Vec3 from = Vec3::Zero();  // where it starts
};

// Of the neighbouring pairs lines[i], lines[i + 1] (cyclically: the lines form a loop around the
// part) for i in [firstPair, endPair), those along which inner points of one line lie within `gap`
// of the other line over at least `minStretch` of its length (0: at one point). Points within
// `closureRadius` of `closure` do not count: every generatrix of a closed part ends there.
MergedNeighbours findMergedNeighbours(const std::vector<Polyline>& lines, size_t firstPair, size_t endPair,
                                      double gap, double minStretch, const std::optional<Vec3>& closure,
                                      double closureRadius);

}  // namespace spira::geodesic
