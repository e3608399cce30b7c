#pragma once

#include <cmath>

#include "spira/base/units.h"
#include "spira/path/trajectory.h"

namespace spira::test {

// A spiral on a vertical cylinder wall, as the spiral builder lays it: counter-clockwise seen from
// +Z, rising `layer` mm per revolution from z = z0. n is the outward radial direction, t the unit
// chord to the next point projected on the tangent plane, b = n x t (close to +Z).
inline Trajectory helixPlan(double radius, double layer, int revolutions, int pointsPerRevolution,
                            double z0 = 1.0)
{
  Trajectory plan;
  const int count = revolutions * pointsPerRevolution;
  const auto at = [&](int k) {
    const double phi = 2.0 * kPi * k / pointsPerRevolution;
    return Vec3(radius * std::cos(phi), radius * std::sin(phi), z0 + layer * k / pointsPerRevolution);
  };
  for (int k = 0; k < count; ++k) {
    TrajectoryPoint p;
    const double phi = 2.0 * kPi * k / pointsPerRevolution;
    p.position = at(k);
    p.normal = Vec3(std::cos(phi), std::sin(phi), 0.0);
    const Vec3 chord = at(k + 1) - at(k);
    p.tangent = (chord - chord.dot(p.normal) * p.normal).normalized();
    p.build = p.normal.cross(p.tangent);
    p.revolution = k / pointsPerRevolution;
    p.generatrix = k % pointsPerRevolution;
    p.height = layer;
    plan.points.push_back(p);
  }
  return plan;
}

// A straight wall point travelling along +X or -X at (x, y, z), building +Z.
inline TrajectoryPoint wallPoint(double x, double y, double z, bool forward)
{
  TrajectoryPoint p;
  p.position = Vec3(x, y, z);
  p.tangent = forward ? Vec3(1, 0, 0) : Vec3(-1, 0, 0);
  p.build = Vec3::UnitZ();
  p.normal = p.tangent.cross(p.build);  // n = t x b, so that b = n x t
  return p;
}

}  // namespace spira::test
