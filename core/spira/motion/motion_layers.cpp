#include "spira/motion/motion_layers.h"

#include <cmath>

#include "spira/base/units.h"
#include "spira/kinematics/angle_wrap.h"

namespace spira {

namespace {

// Angle of p about the axis (point, unit direction), against a fixed reference orthogonal to it.
double polarAngle(const Vec3& p, const Vec3& point, const Vec3& direction, const Vec3& reference)
{
  Vec3 d = p - point;
  d -= d.dot(direction) * direction;
  return std::atan2(direction.dot(reference.cross(d)), reference.dot(d));
}

}  // namespace

std::vector<MotionLayer> splitLayers(const Trajectory& path, const MotionParams& params)
{
  std::vector<MotionLayer> layers;
  const size_t n = path.size();
  for (size_t i = 0; i < n;) {
    MotionLayer layer;
    layer.first = i;
    layer.path = path.points[i].path;
    layer.revolution = path.points[i].revolution;
    size_t end = i + 1;
    while (end < n && path.points[end].path == layer.path && path.points[end].revolution == layer.revolution)
      ++end;
    layer.count = end - i;
    layer.hasNext = end < n;
    layer.x.resize(layer.count);
    if (params.variable == SpinVariable::PointIndex) {
      for (size_t m = 0; m < layer.count; ++m)
        layer.x[m] = static_cast<double>(m) / static_cast<double>(layer.count);
      layer.xNext = 1.0;
    } else {
      const Vec3 dir = params.axisDirection.normalized();
      const Vec3 ref = dir.unitOrthogonal();
      double previous = polarAngle(path.points[i].position, params.axisPoint, dir, ref);
      const double start = previous;
      for (size_t m = 0; m <= layer.count && i + m < n; ++m) {
        const double a =
            nearestBranch(polarAngle(path.points[i + m].position, params.axisPoint, dir, ref), previous);
        previous = a;
        const double x = (a - start) / (2.0 * kPi);
        if (m < layer.count)
          layer.x[m] = x;
        else
          layer.xNext = x;
      }
    }
    layers.push_back(std::move(layer));
    i = end;
  }
  return layers;
}

}  // namespace spira
