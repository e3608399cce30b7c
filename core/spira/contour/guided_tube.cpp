#include "spira/contour/guided_tube.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "spira/base/error.h"

namespace spira {
namespace {

struct Frames {
  double t0 = 0.0, dt = 0.0;
  std::vector<Vec3> normal, binormal;
};

Vec3 tangentAt(const std::function<Vec3(double)>& guide, double t, double h)
{
  const Vec3 d = guide(t + h) - guide(t - h);
  if (!(d.norm() > 0.0)) throw InputError("the guide curve stops (no tangent) at t = " + std::to_string(t));
  return d.normalized();
}

}  // namespace

std::function<Vec3(double)> polylineGuide(std::vector<Vec3> points)
{
  if (points.size() < 2) throw InputError("a guide curve needs at least 2 points");
  std::vector<double> at{0.0};
  for (size_t i = 1; i < points.size(); ++i) {
    const double step = (points[i] - points[i - 1]).norm();
    if (!(step > 1e-9))
      throw InputError("the guide curve repeats its point " + std::to_string(i), "remove repeated points");
    at.push_back(at.back() + step);
  }
  return [points = std::move(points), at = std::move(at)](double t) -> Vec3 {
    const size_t n = points.size();
    if (t <= 0.0) return points[0] + t * (points[1] - points[0]).normalized();
    if (t >= at.back()) return points[n - 1] + (t - at.back()) * (points[n - 1] - points[n - 2]).normalized();
    const size_t i = size_t(std::upper_bound(at.begin(), at.end(), t) - at.begin()) - 1;
    // Centripetal Catmull-Rom (Barry-Goldman) on p0 p1 p2 p3, the ends mirrored.
    const Vec3& p1 = points[i];
    const Vec3& p2 = points[i + 1];
    const Vec3 p0 = i > 0 ? points[i - 1] : Vec3(2.0 * p1 - p2);
    const Vec3 p3 = i + 2 < n ? points[i + 2] : Vec3(2.0 * p2 - p1);
    const double t0 = 0.0, t1 = t0 + std::sqrt((p1 - p0).norm()), t2 = t1 + std::sqrt((p2 - p1).norm()),
                 t3 = t2 + std::sqrt((p3 - p2).norm());
    const double u = t1 + (t - at[i]) / (at[i + 1] - at[i]) * (t2 - t1);
    const Vec3 a1 = (t1 - u) / (t1 - t0) * p0 + (u - t0) / (t1 - t0) * p1;
    const Vec3 a2 = (t2 - u) / (t2 - t1) * p1 + (u - t1) / (t2 - t1) * p2;
    const Vec3 a3 = (t3 - u) / (t3 - t2) * p2 + (u - t2) / (t3 - t2) * p3;
    const Vec3 b1 = (t2 - u) / (t2 - t0) * a1 + (u - t0) / (t2 - t0) * a2;
    const Vec3 b2 = (t3 - u) / (t3 - t1) * a2 + (u - t1) / (t3 - t1) * a3;
    return (t2 - u) / (t2 - t1) * b1 + (u - t1) / (t2 - t1) * b2;
  };
}

double guideLength(const std::function<Vec3(double)>& guide, double t0, double t1, int samples)
{
  double length = 0.0;
  Vec3 previous = guide(t0);
  for (int k = 1; k <= samples; ++k) {
    const Vec3 p = guide(t0 + (t1 - t0) * k / samples);
    length += (p - previous).norm();
    previous = p;
  }
  return length;
}

TubeSurface guidedTube(std::function<Vec3(double)> guide, std::function<double(double)> radius, double t0,
                       double t1, int samples)
{
  if (!(t1 > t0)) throw InputError("the guide's parameter range is empty", "give t1 > t0");
  if (samples < 16) throw InputError("the guide needs at least 16 frame samples");
  auto frames = std::make_shared<Frames>();
  frames->t0 = t0;
  frames->dt = (t1 - t0) / samples;
  const double h = 1e-3 * frames->dt;
  Vec3 tangent = tangentAt(guide, t0, h);
  // The first normal: the axis least aligned with the tangent, made perpendicular to it.
  Vec3 axis = Vec3::UnitX();
  if (std::abs(tangent.x()) > std::abs(tangent.y())) axis = Vec3::UnitY();
  if (std::abs(axis.dot(tangent)) > std::abs(Vec3::UnitZ().dot(tangent))) axis = Vec3::UnitZ();
  Vec3 normal = (axis - axis.dot(tangent) * tangent).normalized();
  for (int k = 0; k <= samples; ++k) {
    const Vec3 next = tangentAt(guide, t0 + k * frames->dt, h);
    // Parallel transport: the rotation that takes the previous tangent to this one, applied to the normal.
    const Vec3 axisOfTurn = tangent.cross(next);
    const double s = axisOfTurn.norm(), c = tangent.dot(next);
    if (s > 1e-15) {
      const Vec3 u = axisOfTurn / s;
      normal = normal * c + u.cross(normal) * s + u * u.dot(normal) * (1.0 - c);
    }
    normal = (normal - normal.dot(next) * next).normalized();
    tangent = next;
    frames->normal.push_back(normal);
    frames->binormal.push_back(next.cross(normal));
  }
  TubeSurface tube;
  tube.t0 = t0;
  tube.tEnd = t1;
  tube.at = [guide = std::move(guide), radius = std::move(radius), frames](double t, double v) {
    const double x = std::clamp((t - frames->t0) / frames->dt, 0.0, double(frames->normal.size() - 1));
    const size_t k = std::min(size_t(x), frames->normal.size() - 2);
    const double w = x - double(k);
    const Vec3 n = ((1.0 - w) * frames->normal[k] + w * frames->normal[k + 1]).normalized();
    Vec3 b = (1.0 - w) * frames->binormal[k] + w * frames->binormal[k + 1];
    b = (b - b.dot(n) * n).normalized();  // exactly across n, so the profile keeps its radius
    return Vec3(guide(t) + radius(t) * (std::cos(v) * n + std::sin(v) * b));
  };
  return tube;
}

}  // namespace spira
