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
