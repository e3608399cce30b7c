#include "spira/mesh/mesh_primitives.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "spira/base/error.h"
#include "spira/base/units.h"

namespace spira {

namespace {

// cos and sin of 2*pi*j/n, exact at the quarter turns, so vertices on the axes have exact zeros.
void unitCircle(int j, int n, double& c, double& s)
{
  if ((4 * j) % n == 0) {
    static const double kCos[4] = {1.0, 0.0, -1.0, 0.0};
    static const double kSin[4] = {0.0, 1.0, 0.0, -1.0};
    const int q = (4 * j / n) % 4;
    c = kCos[q];
    s = kSin[q];
    return;
  }
  const double a = 2.0 * kPi * static_cast<double>(j) / static_cast<double>(n);
  c = std::cos(a);
  s = std::sin(a);
}

void require(bool ok, const std::string& what, const std::string& hint)
{
  if (!ok) throw InputError(what, hint);
}

void requirePositive(double v, const char* name)
{
  require(std::isfinite(v) && v > 0.0,
          std::string(name) + " must be a positive length, not " + std::to_string(v),
          "give a size in millimetres greater than zero");
}

void requireCounts(int segments, int rings)
{
  require(segments >= 3, "a surface of revolution needs at least 3 segments, not " + std::to_string(segments),
          "use 3 or more segments around the axis");
  require(rings >= 1, "a surface of revolution needs at least 1 ring, not " + std::to_string(rings),
          "use 1 or more rings along the axis");
}

// Exactly `to` at i == n, so rims land exactly on their nominal height.
double lerp(double from, double to, int i, int n)
{
  return i == n ? to : from + (to - from) * static_cast<double>(i) / static_cast<double>(n);
}

}  // namespace

TriangleMesh makeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments)
{
  requireCounts(segments, 1);
  const int n = static_cast<int>(profile.size());
  require(n >= 2, "a revolved profile needs at least 2 points, not " + std::to_string(n),
          "give the profile as (r, z) points from bottom to top");
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d& p = profile[i];
    require(p.allFinite() && p.x() >= 0.0,
            "profile point " + std::to_string(i) + " is not a finite point with radius >= 0",
            "give radii >= 0 and finite heights in millimetres");
    require(p.x() > 0.0 || i == 0 || i == n - 1,
            "profile point " + std::to_string(i) + " lies on the axis between other points",
            "only the first and last profile points may have radius 0 (they close the surface at a pole)");
    require(i == 0 || p != profile[i - 1],
            "profile points " + std::to_string(i - 1) + " and " + std::to_string(i) + " are the same",
            "remove repeated profile points");
  }
  require(profile[0].x() > 0.0 || profile[n - 1].x() > 0.0 || n > 2, "the profile runs along the axis",
          "give at least one point off the axis");

  TriangleMesh m;
  std::vector<int> rowStart(n);
  for (int i = 0; i < n; ++i) {
    rowStart[i] = static_cast<int>(m.vertices.size());
    const double r = profile[i].x(), z = profile[i].y();
    if (r == 0.0) {
      m.vertices.emplace_back(0.0, 0.0, z);  // pole
      continue;
    }
    for (int j = 0; j < segments; ++j) {
      double c, s;
      unitCircle(j, segments, c, s);
      m.vertices.emplace_back(r * c, r * s, z);
    }
  }
  // Quad (a, b) on row i, (d, c) on row i + 1, b and c one step further round: (a, b, c) and
  // (a, c, d) face to the right of the profile's direction, so outwards for a profile running up
  // the outside. At a pole the quad collapses into one triangle.
  for (int i = 0; i + 1 < n; ++i) {
    const bool poleBelow = profile[i].x() == 0.0, poleAbove = profile[i + 1].x() == 0.0;
    for (int j = 0; j < segments; ++j) {
      const int j1 = (j + 1) % segments;
      const int a = poleBelow ? rowStart[i] : rowStart[i] + j;
      const int b = poleBelow ? rowStart[i] : rowStart[i] + j1;
      const int c = poleAbove ? rowStart[i + 1] : rowStart[i + 1] + j1;
      const int d = poleAbove ? rowStart[i + 1] : rowStart[i + 1] + j;
      if (!poleBelow) m.faces.push_back({a, b, c});
      if (!poleAbove) m.faces.push_back({a, c, d});
    }
  }
  return m;
}

TriangleMesh makeRevolvedSolid(const std::vector<Eigen::Vector2d>& closedProfile, int segments)
{
  require(closedProfile.size() >= 3, "a closed profile needs at least 3 points",
          "give the profile's corners");
  for (const Eigen::Vector2d& p : closedProfile)
    require(p.x() > 0.0, "a solid's closed profile must stay off the axis", "give radii > 0");
  std::vector<Eigen::Vector2d> profile = closedProfile;
  profile.push_back(closedProfile.front());
  TriangleMesh m = makeRevolved(profile, segments);
  // The last row repeats the first: its vertices (at the end of the list) are mapped onto it.
  const int lastRow = static_cast<int>(m.vertices.size()) - segments;
  for (Face& f : m.faces)
    for (int& v : f)
      if (v >= lastRow) v -= lastRow;
  m.vertices.resize(static_cast<size_t>(lastRow));
  return m;
}

TriangleMesh makeTubeSolid(double outerRadius, double innerRadius, double height, int segments, int rings)
{
  requirePositive(outerRadius, "outer radius");
  requirePositive(innerRadius, "inner radius");
  requirePositive(height, "height");
  requireCounts(segments, rings);
  require(innerRadius < outerRadius, "the inner radius must be smaller than the outer one",
          "give an inner radius below the outer radius");
  // Down the inside, out along the bottom, up the outside, in along the top.
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= rings; ++i) profile.emplace_back(innerRadius, lerp(height, 0.0, i, rings));
  for (int i = 0; i <= rings; ++i) profile.emplace_back(outerRadius, lerp(0.0, height, i, rings));
  return makeRevolvedSolid(profile, segments);
}

TriangleMesh makeOpenCylinder(double radius, double height, int segments, int rings)
{
  return makeOpenCone(radius, radius, height, segments, rings);
}

TriangleMesh makeOpenCone(double r0, double r1, double height, int segments, int rings)
{
  requireCounts(segments, rings);
  requirePositive(height, "height");
  require(std::isfinite(r0) && std::isfinite(r1) && r0 >= 0.0 && r1 >= 0.0 && (r0 > 0.0 || r1 > 0.0),
          "cone radii " + std::to_string(r0) + " and " + std::to_string(r1) + " are not valid",
          "give radii >= 0 with at least one of them greater than zero");
  std::vector<Eigen::Vector2d> profile;
  for (int i = 0; i <= rings; ++i) profile.emplace_back(lerp(r0, r1, i, rings), lerp(0.0, height, i, rings));
  return makeRevolved(profile, segments);
}

namespace {

// The torus section of makeBentTube whose profile point v starts at bend angle start(v). Counter-clockwise
// seen from outside: the profile turns from +X (outward) to +Y as v grows and the tube runs up +Z at its
// base.
TriangleMesh torusSection(double bendRadius, double radius, const std::function<double(double)>& start,
                          double angle, int segments, int rings)
{
  return makeTubeSurface(
      [&](double u, double v) {
        const double t0 = start(v);
        const double t = t0 + (angle - t0) * u;
        const Vec3 outward(std::cos(t), 0.0, std::sin(t));
        const Vec3 centre(bendRadius * std::cos(t) - bendRadius, 0.0, bendRadius * std::sin(t));
        return Vec3(centre + radius * (std::cos(v) * outward + std::sin(v) * Vec3::UnitY()));
      },
      segments, rings);
}

void requireBend(double bendRadius, double radius, double angle)
{
  requirePositive(radius, "radius");
  require(std::isfinite(bendRadius) && bendRadius > radius,
          "a bend radius of " + std::to_string(bendRadius) + " mm folds a tube of radius " +
              std::to_string(radius) + " mm onto itself",
          "give a bend radius larger than the tube's radius");
  require(std::isfinite(angle) && angle > 0.0 && angle < 2.0 * kPi,
          "a bend of " + std::to_string(angle) + " rad is not a section of a torus", "give 0 < angle < 2 pi");
}

}  // namespace

TriangleMesh makeTubeSurface(const std::function<Vec3(double u, double v)>& at, int segments, int rings)
{
  requireCounts(segments, rings);
  TriangleMesh m;
  for (int a = 0; a <= rings; ++a)
    for (int k = 0; k < segments; ++k) m.vertices.push_back(at(double(a) / rings, 2.0 * kPi * k / segments));
  const auto index = [segments](int a, int k) { return a * segments + (k % segments); };
  for (int a = 0; a < rings; ++a)
    for (int k = 0; k < segments; ++k) {
      m.faces.push_back({index(a, k), index(a, k + 1), index(a + 1, k + 1)});
      m.faces.push_back({index(a, k), index(a + 1, k + 1), index(a + 1, k)});
    }
  return m;
}

TriangleMesh makeBentTube(double bendRadius, double radius, double angle, int segments, int rings)
{
  requireCounts(segments, rings);
  requireBend(bendRadius, radius, angle);
  return torusSection(
      bendRadius, radius, [](double) { return 0.0; }, angle, segments, rings);
}

TriangleMesh makePipeAbout(double radius, char axis, double length)
{
  requirePositive(radius, "radius");
  requirePositive(length, "length");
  require(axis == 'x' || axis == 'y' || axis == 'z', std::string("axis '") + axis + "' is not x, y or z",
          "give the axis as x, y or z");
  // Edges of 2 mm, longer on a pipe so large that it would take more than about 200,000 triangles.
  const double edge = std::max(2.0, std::sqrt(2.0 * 2.0 * kPi * radius * length / 200000.0));
  const int rings = std::max(2, int(std::ceil(length / edge)));
  TriangleMesh m = makeOpenCylinder(radius, length, std::max(8, segmentsForEdge(radius, edge)), rings);
  for (Vec3& v : m.vertices) {
    v.z() -= 0.5 * length;
    if (axis == 'x') v = Vec3(v.z(), v.x(), v.y());
    if (axis == 'y') v = Vec3(v.y(), v.z(), v.x());
  }
  return m;
}

TriangleMesh makeTorusOnCylinder(double bendRadius, double radius, double cylinderRadius, double angle,
                                 int segments, int rings)
{
  requireCounts(segments, rings);
  requireBend(bendRadius, radius, angle);
  // 004_bd0df31205c0c3c0.txt Eq. 2.17: where profile point v leaves the cylinder x^2 + z^2 = Rc^2.
  const auto start = [=](double v) {
    const double rho = bendRadius + radius * std::cos(v);
    const double c =
        (bendRadius * bendRadius - cylinderRadius * cylinderRadius + rho * rho) / (2.0 * bendRadius * rho);
    return std::acos(std::clamp(c, -1.0, 1.0));
  };
  for (int k = 0; k < segments; ++k) {
    const double v = 2.0 * kPi * k / segments;
    const double rho = bendRadius + radius * std::cos(v);
    const double c =
        (bendRadius * bendRadius - cylinderRadius * cylinderRadius + rho * rho) / (2.0 * bendRadius * rho);
    require(
        std::abs(c) <= 1.0 && start(v) < angle,
        "a cylinder of radius " + std::to_string(cylinderRadius) + " mm does not cut the bent tube across",
        "give a cylinder that the tube's base leaves and its end lies outside of");
  }
  return torusSection(bendRadius, radius, start, angle, segments, rings);
}

TriangleMesh makeHemisphere(double radius, int segments, int rings)
{
  requireCounts(segments, rings);
  requirePositive(radius, "radius");
  std::vector<Eigen::Vector2d> profile;
  profile.emplace_back(radius, 0.0);
  for (int i = 1; i < rings; ++i) {
    const double phi = 0.5 * kPi * static_cast<double>(i) / static_cast<double>(rings);
    profile.emplace_back(radius * std::cos(phi), radius * std::sin(phi));
  }
  profile.emplace_back(0.0, radius);
  return makeRevolved(profile, segments);
}

TriangleMesh makeTetrahedron(double edge)
{
  requirePositive(edge, "edge");
  // Alternate corners of a cube of side 2 have edges 2*sqrt(2).
  const double s = edge / (2.0 * std::sqrt(2.0));
  TriangleMesh m;
  m.vertices = {Vec3(s, s, s), Vec3(s, -s, -s), Vec3(-s, s, -s), Vec3(-s, -s, s)};
  m.faces = {{0, 1, 2}, {1, 0, 3}, {2, 1, 3}, {0, 2, 3}};
  return m;
}

int segmentsForEdge(double radius, double edge)
{
  requirePositive(radius, "radius");
  requirePositive(edge, "edge");
  const double n = std::round(2.0 * kPi * radius / edge);
  require(n < 1e8,
          "an edge of " + std::to_string(edge) + " mm on a radius of " + std::to_string(radius) +
              " mm needs too many segments",
          "choose a longer edge");
  return std::max(3, static_cast<int>(n));
}

int ringsForEdge(double length, double edge)
{
  requirePositive(length, "length");
  requirePositive(edge, "edge");
  const double n = std::round(length / edge);
  require(n < 1e8,
          "an edge of " + std::to_string(edge) + " mm along " + std::to_string(length) +
              " mm needs too many rings",
          "choose a longer edge");
  return std::max(1, static_cast<int>(n));
}

}  // namespace spira
