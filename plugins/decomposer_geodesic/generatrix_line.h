#pragma once

#include <vector>

#include "spira/path/trajectory.h"

namespace spira::geodesic {

// A generatrix while it is built: points from the base up, a unit surface normal at each.
struct GeneratrixLine {
  Polyline points;
  std::vector<Vec3> normals;
  double angle = 0.0;        // of its base point, about the vertical axis through the base centroid
  bool fillIn = false;       // inserted by the coverage check, not a geodesic
  double exactLength = 0.0;  // geodesics: the exact distance between the ends, mm (0 for fill-ins)
  double length() const;
};

// `line` resampled to `count` (>= 2) points at equal fractions of its arc length, the normals
// interpolated linearly and renormalised; the end points are kept exactly.
GeneratrixLine resampleLine(const GeneratrixLine& line, size_t count);

}  // namespace spira::geodesic
