#pragma once

#include <cmath>
#include <functional>
#include <utility>

#include "spira/base/units.h"
#include "spira/path/trajectory.h"

// Generatrices of analytic surfaces, made in code, ordered counter-clockwise seen from +z (the
// travel direction), with outward unit normals.
namespace spira::test {

inline double angleOf(int i, int n)
{
  return 2.0 * kPi * i / n;
}

// Generatrix i of n at angle a = 2 pi i / n: `points` points position(i, a, k), k = 0 .. points - 1,
// each with the radial unit normal (the surface is upright wherever it is).
inline Generatrices radialLines(int n, int points, const std::function<Vec3(int, double, int)>& position)
{
  Generatrices g;
  for (int i = 0; i < n; ++i) {
    const double a = angleOf(i, n);
    const Vec3 radial(std::cos(a), std::sin(a), 0.0);
    Polyline line;
    std::vector<Vec3> normals;
    for (int k = 0; k < points; ++k) {
      line.push_back(position(i, a, k));
      normals.push_back(radial);
    }
    g.lines.push_back(line);
    g.normals.push_back(normals);
  }
  return g;
}

// Vertical lines on the cylinder of radius R about z, generatrix i at angle 2 pi i / n, from z = 0
// to z = length(i), with `points` evenly spaced points each.
inline Generatrices cylinderLines(double R, int n, const std::function<double(int)>& length, int points)
{
  return radialLines(n, points, [&](int i, double a, int k) {
    return Vec3(R * std::cos(a), R * std::sin(a), length(i) * k / (points - 1));
  });
}

inline Generatrices cylinder(double R, double H, int n, int points)
{
  return cylinderLines(
      R, n, [H](int) { return H; }, points);
}

// Straight lines on the cone frustum from radius R0 at z = 0 to radius R1 at z = H.
inline Generatrices coneLines(double R0, double R1, double H, int n, int points)
{
  Generatrices g;
  for (int i = 0; i < n; ++i) {
    const double a = angleOf(i, n);
    const Vec3 radial(std::cos(a), std::sin(a), 0.0);
    // Outward normal of r(z) = R0 + (R1 - R0) z / H: radial minus dr/dz along z.
    const Vec3 normal = (radial - (R1 - R0) / H * Vec3::UnitZ()).normalized();
    Polyline line;
    std::vector<Vec3> normals;
    for (int k = 0; k < points; ++k) {
      const double z = H * k / (points - 1);
      line.push_back((R0 + (R1 - R0) * z / H) * radial + Vec3(0, 0, z));
      normals.push_back(normal);
    }
    g.lines.push_back(line);
    g.normals.push_back(normals);
  }
  return g;
}

// Meridians of the hemisphere of radius R centred at the origin, from the equator (z = 0) to the
// pole, which is the closure point.
inline Generatrices hemisphereMeridians(double R, int n, int points)
{
  Generatrices g;
  g.hasClosurePoint = true;
  g.closurePoint = Vec3(0, 0, R);
  for (int i = 0; i < n; ++i) {
    const double a = angleOf(i, n);
    Polyline line;
    std::vector<Vec3> normals;
    for (int k = 0; k < points; ++k) {
      const double lat = 0.5 * kPi * k / (points - 1);
      const Vec3 unit = k + 1 == points
                            ? Vec3::UnitZ()
                            : Vec3(std::cos(lat) * std::cos(a), std::cos(lat) * std::sin(a), std::sin(lat));
      line.push_back(R * unit);
      normals.push_back(unit);
    }
    g.lines.push_back(line);
    g.normals.push_back(normals);
  }
  return g;
}

// Length the default (uniform-helix) start-up and termination take on every generatrix at
// h ± 10 % with n points per revolution, sized for the layer step c: four full ramps each way
// (8 h), the transition h_min -> h_min + c (n-1)/n - 0.8 h and back, and a constant revolution at
// c each way: 9 h + c (3n - 1) / n.
inline double helixRampLength(double h, double c, int n)
{
  return 9.0 * h + c * (3.0 * n - 1.0) / n;
}

// For generatrices all of length `length`: the layer count consistent with its own step, where
// d = (length - ramps(d)) / n_layer and n_layer = floor((length - ramps) / h_min) (floor) or
// round((length - ramps) / h) (centred). Returns {n_layer, d}.
inline std::pair<int, double> uniformHelixLayers(double length, double h, int n, bool floorMode)
{
  const double k = (3.0 * n - 1.0) / n;
  for (int layers = 1; layers < 100000; ++layers) {
    const double d = (length - 9.0 * h) / (layers + k);
    const double modulated = length - helixRampLength(h, d, n);
    const int count = floorMode ? static_cast<int>(std::floor(modulated / (0.9 * h) + 1e-9))
                                : static_cast<int>(std::lround(modulated / h));
    if (count == layers) return {layers, d};
  }
  return {0, 0.0};
}

}  // namespace spira::test
