#pragma once

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "spira/base/units.h"
#include "spira/path/trajectory.h"

// Trajectories of analytic shapes, made in code, for the path-preparation tests and benchmark.
namespace spira::test {

// The frame of a point on the circle of radius R about z at angle a, travelling counter-clockwise:
// n radial outwards, t the tangent, b = n x t = +z.
inline TrajectoryPoint circlePoint(double R, double a)
{
  TrajectoryPoint p;
  p.position = Vec3(R * std::cos(a), R * std::sin(a), 0.0);
  p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
  p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
  p.build = p.normal.cross(p.tangent);
  p.travelSpeed = 10.0;
  p.wireFeed = 100.0;
  p.height = 2.0;
  return p;
}

// The half circle R from angle 0 to pi through `count` irregularly spaced angles (sorted uniform
// draws of a fixed seed), ends included.
inline std::vector<double> irregularAngles(int count, unsigned seed, double span = kPi)
{
  std::mt19937 rng(seed);
  std::vector<double> a{0.0, span};
  for (int i = 0; i < count - 2; ++i) a.push_back(span * (rng() / 4294967296.0));
  std::sort(a.begin(), a.end());
  return a;
}

// A helix on the cylinder of radius R about z, `pitch` mm per revolution, `turns` turns, points about
// `spacing` mm apart. The deposit height and the travel speed and wire feed are modulated along the
// angle theta: height = 2 + hAmp sin(hWaves theta), TS = 8 + sin(3 theta), WFS = 100 + 10 sin(3 theta).
inline Trajectory modulatedHelix(double R, double pitch, double turns, double spacing, double hAmp,
                                 double hWaves)
{
  Trajectory tr;
  const double total = 2.0 * kPi * turns;
  const int n = static_cast<int>(std::ceil(total * R / spacing)) + 1;
  const double climb = pitch / (2.0 * kPi);  // dz / dtheta
  for (int i = 0; i < n; ++i) {
    const double a = total * i / (n - 1);
    TrajectoryPoint p;
    p.position = Vec3(R * std::cos(a), R * std::sin(a), climb * a);
    p.normal = Vec3(std::cos(a), std::sin(a), 0.0);
    p.tangent = Vec3(-R * std::sin(a), R * std::cos(a), climb).normalized();
    p.build = p.normal.cross(p.tangent);
    p.revolution = static_cast<int>(std::floor(a / (2.0 * kPi)));
    p.height = 2.0 + hAmp * std::sin(hWaves * a);
    p.travelSpeed = 8.0 + std::sin(3.0 * a);
    p.wireFeed = 100.0 + 10.0 * std::sin(3.0 * a);
    tr.points.push_back(p);
  }
  return tr;
}

// Points along +x from 0 to `length`, `count` of them evenly spaced, constant channels.
inline Trajectory straightLine(double length, int count)
{
  Trajectory tr;
  for (int i = 0; i < count; ++i) {
    TrajectoryPoint p;
    p.position = Vec3(length * i / (count - 1), 0.0, 0.0);
    p.normal = Vec3(0, -1, 0);
    p.tangent = Vec3(1, 0, 0);
    p.build = p.normal.cross(p.tangent);
    p.travelSpeed = 10.0;
    p.wireFeed = 100.0;
    p.height = 2.0;
    tr.points.push_back(p);
  }
  return tr;
}

}  // namespace spira::test
