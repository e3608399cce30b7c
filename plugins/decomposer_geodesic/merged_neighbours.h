#pragma once

#include <optional>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira::geodesic {

// Where neighbouring generatrices run together: shortest paths on a mesh bend only at vertices
// whose angles sum to more than 2 pi (the saddles of a waist, a faceted or corrugated wall), so
// paths from neighbouring base points can funnel through the same vertex and share the rest of
// their way.
struct MergedNeighbours {
  size_t pairs = 0;          // neighbouring pairs that run together
  size_t first = 0;          // the longest stretch: lines[first] and the next one (cyclically)
  double stretch = 0.0;      // its length along lines[first], mm
  Vec3 from = Vec3::Zero();  // where it starts
};

// Of the neighbouring pairs lines[i], lines[i + 1] (cyclically: the lines form a loop around the
// part) for i in [firstPair, endPair), those along which a point of one line lies within `gap` of
// the other line over more than `minStretch` of its length. Points within `closureRadius` of
// `closure` do not count: every generatrix of a closed part ends there.
MergedNeighbours findMergedNeighbours(const std::vector<Polyline>& lines, size_t firstPair, size_t endPair,
                                      double gap, double minStretch, const std::optional<Vec3>& closure,
                                      double closureRadius);

}  // namespace spira::geodesic
