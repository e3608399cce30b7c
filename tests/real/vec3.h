#pragma once

#include <cmath>

namespace spira::test::real {

// The test-side checker's own 3-vector: it shares no geometry type with the product it judges.
struct V3 {
  double x = 0, y = 0, z = 0;
  V3() = default;
  V3(double ax, double ay, double az) : x(ax), y(ay), z(az) {}
  V3 operator+(const V3& o) const { return {x + o.x, y + o.y, z + o.z}; }
  V3 operator-(const V3& o) const { return {x - o.x, y - o.y, z - o.z}; }
  V3 operator*(double s) const { return {x * s, y * s, z * s}; }
  double dot(const V3& o) const { return x * o.x + y * o.y + z * o.z; }
  V3 cross(const V3& o) const { return {y * o.z - z * o.y, z * o.x - x * o.z, x * o.y - y * o.x}; }
  double norm() const { return std::sqrt(dot(*this)); }
  V3 unit() const
  {
    const double n = norm();
    return n > 0 ? *this * (1.0 / n) : V3{};
  }
};

// Closest point to `p` on the segment [a, c].
inline V3 closestOnSegment(const V3& p, const V3& a, const V3& c)
{
  const V3 d = c - a;
  const double len2 = d.dot(d);
  if (len2 <= 0) return a;
  double s = (p - a).dot(d) / len2;
  s = s < 0 ? 0 : (s > 1 ? 1 : s);
  return a + d * s;
}

}  // namespace spira::test::real
