#pragma once

#include <cstddef>

#include "spira/path/trajectory.h"

namespace spira {

// A dwell breaks the deposition for cooling (000_dbb97c2716e10cc3.txt §5.6.4 names the cooling
// pause as a remedy for overheating): the torch reaches point i, the arc stops, the torch lifts
// along its axis to a safe pose and waits there dwell_s seconds, comes back to point i and strikes
// again before depositing on to point i + 1. The channel holds, per point, that wait (0 where the
// torch does not stop). Wire cannot be fed without depositing it, so the arc is off during the wait:
// every dwell adds one arc start.
inline constexpr const char* kDwellChannel = "dwell_s";

// The wait at point i, s (0 when the trajectory has no dwell channel).
inline double dwellAt(const Trajectory& t, size_t i)
{
  const auto it = t.extra.find(kDwellChannel);
  return it == t.extra.end() || i >= it->second.size() ? 0.0 : it->second[i];
}

// How many points of `t` wait, and the waits' sum, s.
struct DwellTotals {
  size_t count = 0;
  double seconds = 0.0;
};

inline DwellTotals dwellTotals(const Trajectory& t)
{
  DwellTotals d;
  const auto it = t.extra.find(kDwellChannel);
  if (it == t.extra.end()) return d;
  for (double s : it->second)
    if (s > 0.0) {
      ++d.count;
      d.seconds += s;
    }
  return d;
}

inline bool hasDwell(const Trajectory& t)
{
  const auto it = t.extra.find(kDwellChannel);
  if (it == t.extra.end()) return false;
  for (double d : it->second)
    if (d > 0.0) return true;
  return false;
}

}  // namespace spira
