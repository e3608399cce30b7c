#pragma once

#include <cmath>

#include "spira/path/trajectory.h"

namespace spira::test {

// A cylindrical wall laid as flat revolutions of `perRevolution` points at z = height, 2 height, ...
// (each revolution climbs to the next one on its last segment), at travel speed `speed` (mm/s).
inline Trajectory cylinderWall(double radius, int revolutions, int perRevolution, double height, double speed)
{
  Trajectory t;
  for (int r = 0; r < revolutions; ++r)
    for (int g = 0; g < perRevolution; ++g) {
      const double a = 2.0 * 3.14159265358979323846 * g / perRevolution;
      TrajectoryPoint p;
      p.position = Vec3(radius * std::cos(a), radius * std::sin(a), height * (r + 1));
      p.revolution = r;
      p.generatrix = g;
      p.height = height;
      p.travelSpeed = speed;
      t.points.push_back(p);
    }
  return t;
}

// A hemispherical dome of radius `radius` laid as revolutions at polar steps of `height` mm of arc,
// `perRevolution` points each, closed by one point at the apex (the closure point).
inline Trajectory hemisphereDome(double radius, double height, int perRevolution, double speed)
{
  Trajectory t;
  const int revolutions = int(0.5 * 3.14159265358979323846 * radius / height);
  for (int r = 0; r < revolutions; ++r) {
    const double polar = (r + 0.5) * height / radius;
    for (int g = 0; g < perRevolution; ++g) {
      const double a = 2.0 * 3.14159265358979323846 * g / perRevolution;
      TrajectoryPoint p;
      p.position =
          radius * Vec3(std::cos(polar) * std::cos(a), std::cos(polar) * std::sin(a), std::sin(polar));
      p.revolution = r;
      p.generatrix = g;
      p.height = height;
      p.travelSpeed = speed;
      t.points.push_back(p);
    }
  }
  TrajectoryPoint apex;
  apex.position = Vec3(0.0, 0.0, radius);
  apex.revolution = revolutions;
  apex.travelSpeed = speed;
  t.points.push_back(apex);
  return t;
}

// Area of the triangle (a, b, c), mm2.
inline double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c)
{
  return 0.5 * (b - a).cross(c - a).norm();
}

}  // namespace spira::test
