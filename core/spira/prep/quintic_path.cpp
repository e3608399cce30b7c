#include "spira/prep/quintic_path.h"

#include <cmath>

#include "spira/prep/frame_math.h"

namespace spira {

namespace {

constexpr double kZeroLength = 1e-9;  // mm: shorter intervals are repeated points

double lerp(double a, double b, double u)
{
  return a + u * (b - a);
}

}  // namespace

QuinticPath::QuinticPath(const Trajectory& source, bool smooth, double cornerAngle) : source_(&source)
{
  const auto& pts = source.points;
  const size_t n = pts.size();
  if (n < 2) {
    runBreak_.assign(n, 1);
    return;
  }
  chord_.resize(n - 1);
  straight_.resize(n - 1);
  for (size_t k = 0; k + 1 < n; ++k) {
    chord_[k] = (pts[k + 1].position - pts[k].position).norm();
    straight_[k] = !smooth || chord_[k] < kZeroLength || pts[k].path != pts[k + 1].path ||
                   pts[k].arcOn != pts[k + 1].arcOn;
  }
  runBreak_.assign(n, 0);
  runBreak_[0] = runBreak_[n - 1] = 1;
  for (size_t k = 1; k + 1 < n; ++k) {
    if (straight_[k - 1] || straight_[k]) {
      runBreak_[k] = 1;
      continue;
    }
    const Vec3 d1 = pts[k].position - pts[k - 1].position;
    const Vec3 d2 = pts[k + 1].position - pts[k].position;
    runBreak_[k] = std::atan2(d1.cross(d2).norm(), d1.dot(d2)) > cornerAngle;
  }
}

ParabolaDerivatives QuinticPath::derivativesAt(size_t k, bool rightSide, Vec3 TrajectoryPoint::*member) const
{
  const auto& pts = source_->points;
  const auto x = [&](size_t i) -> const Vec3& { return pts[i].*member; };
  if (interiorOfRun(k)) return parabolaDerivatives(x(k - 1), x(k), x(k + 1), chord_[k - 1], chord_[k], 1);
  if (rightSide) {
    // runBreak_[k + 1] == 0 implies k + 2 exists and interval k + 1 is curved.
    if (k + 2 < pts.size() && interiorOfRun(k + 1))
      return parabolaDerivatives(x(k), x(k + 1), x(k + 2), chord_[k], chord_[k + 1], 0);
    return {(x(k + 1) - x(k)) / chord_[k], Vec3::Zero()};
  }
  if (k >= 2 && interiorOfRun(k - 1))
    return parabolaDerivatives(x(k - 2), x(k - 1), x(k), chord_[k - 2], chord_[k - 1], 2);
  return {(x(k) - x(k - 1)) / chord_[k - 1], Vec3::Zero()};
}

QuinticPath::Curves QuinticPath::curves(size_t k) const
{
  const auto& pts = source_->points;
  const double len = chord_[k];
  const auto build = [&](Vec3 TrajectoryPoint::*member) {
    const ParabolaDerivatives d0 = derivativesAt(k, true, member);
    const ParabolaDerivatives d1 = derivativesAt(k + 1, false, member);
    return Quintic3::hermite(pts[k].*member, len * d0.first, len * len * d0.second, pts[k + 1].*member,
                             len * d1.first, len * len * d1.second);
  };
  Curves c;
  c.position = build(&TrajectoryPoint::position);
  c.normal = build(&TrajectoryPoint::normal);
  c.tangent = build(&TrajectoryPoint::tangent);
  c.build = build(&TrajectoryPoint::build);
  return c;
}

TrajectoryPoint QuinticPath::point(size_t k, double u) const
{
  return isStraight(k) ? point(k, u, Curves{}) : point(k, u, curves(k));
}

TrajectoryPoint QuinticPath::point(size_t k, double u, const Curves& c) const
{
  const TrajectoryPoint& a = source_->points[k];
  const TrajectoryPoint& b = source_->points[k + 1];
  TrajectoryPoint p = u >= 1.0 ? b : a;
  if (isStraight(k)) {
    TrajectoryPoint fa = a, fb = b;
    orthonormaliseFrame(fa);
    orthonormaliseFrame(fb);
    const Mat3 r = frameQuaternion(fa).slerp(u, frameQuaternion(fb)).toRotationMatrix();
    p.position = a.position + u * (b.position - a.position);
    p.normal = r.col(0);
    p.tangent = r.col(1);
    p.build = r.col(2);
  } else {
    p.position = c.position.value(u);
    p.normal = c.normal.value(u);
    p.tangent = c.tangent.value(u);
    p.build = c.build.value(u);
  }
  orthonormaliseFrame(p);
  p.height = lerp(a.height, b.height, u);
  p.travelSpeed = lerp(a.travelSpeed, b.travelSpeed, u);
  p.wireFeed = lerp(a.wireFeed, b.wireFeed, u);
  return p;
}

void QuinticPath::extraValues(size_t k, double u, std::vector<double>& out) const
{
  out.clear();
  for (const auto& [name, values] : source_->extra) out.push_back(lerp(values[k], values[k + 1], u));
}

}  // namespace spira
