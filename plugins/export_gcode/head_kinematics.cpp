#include "head_kinematics.h"

#include <cmath>
#include <optional>

#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/base/units.h"

namespace spira {

namespace {

// Angles within this of a limit count as on it: the limits are written with a few decimals.
constexpr double kLimitSlackDeg = 1e-9;
constexpr double kLimitSlackMm = 1e-9;

Mat3 turn(const Vec3& about, double deg)
{
  return Eigen::AngleAxisd(degToRad(deg), about).toRotationMatrix();
}

// The angle (rad) that turns `from` into `to` about the unit `u`, or none when either lies along u
// (the angle is then free).
std::optional<double> angleAbout(const Vec3& u, const Vec3& from, const Vec3& to)
{
  const Vec3 a = from - u * u.dot(from);
  const Vec3 b = to - u * u.dot(to);
  if (a.norm() < 1e-12 || b.norm() < 1e-12) return std::nullopt;
  return std::atan2(u.dot(a.cross(b)), a.dot(b));
}

std::string vecText(const Vec3& v)
{
  return "(" + roundedText(v.x(), 4) + ", " + roundedText(v.y(), 4) + ", " + roundedText(v.z(), 4) + ")";
}

// The value of `deg` plus whole turns nearest `previous` within [lo, hi], or none.
std::optional<double> nearestTurn(double deg, double previous, double lo, double hi)
{
  const double n0 = std::round((previous - deg) / 360.0);
  std::optional<double> best;
  for (double n = n0 - 1.0; n <= n0 + 1.0; n += 1.0) {
    const double v = deg + 360.0 * n;
    if (v < lo - kLimitSlackDeg || v > hi + kLimitSlackDeg) continue;
    if (!best || std::abs(v - previous) < std::abs(*best - previous)) best = v;
  }
  return best;
}

}  // namespace

HeadPose headForward(const GcodeMachine& m, const HeadAxes& axes)
{
  const Mat3 r1 = turn(m.rotary[0].about, axes.rotaryDeg[0]);
  const Mat3 r2 = turn(m.rotary[1].about, axes.rotaryDeg[1]);
  HeadPose p;
  p.tip = axes.linear + r1 * (m.firstToSecond + r2 * m.secondToTip);
  p.axis = r1 * r2 * m.toolDirection;
  return p;
}

// Paden-Kahan subproblem 2: R1 R2 p = q. R2 p = z lies on both cones, u2.z = u2.p (R2 keeps it) and
// u1.z = u1.q (R1 keeps it), so z = alpha u1 + beta u2 + gamma (u1 x u2) with |z| = |p|.
std::vector<std::array<double, 2>> headOrientations(const GcodeMachine& m, const Vec3& axis,
                                                    double freeFirstDeg)
{
  const Vec3& u1 = m.rotary[0].about;
  const Vec3& u2 = m.rotary[1].about;
  const Vec3& p = m.toolDirection;
  const Vec3 q = axis.normalized();
  const double c = u1.dot(u2);
  const double den = 1.0 - c * c;
  const double alpha = (u1.dot(q) - c * u2.dot(p)) / den;
  const double beta = (u2.dot(p) - c * u1.dot(q)) / den;
  const Vec3 w = u1.cross(u2);
  const double g2 = (1.0 - alpha * alpha - beta * beta - 2.0 * alpha * beta * c) / w.squaredNorm();
  std::vector<std::array<double, 2>> out;
  if (g2 < -1e-12) return out;
  const double g = std::sqrt(std::max(g2, 0.0));
  for (double sign : {1.0, -1.0}) {
    const Vec3 z = alpha * u1 + beta * u2 + sign * g * w;
    const std::optional<double> second = angleAbout(u2, p, z);
    if (!second) continue;  // the machine check keeps the tool off the second axis
    const Mat3 r2 = turn(u2, radToDeg(*second));
    // From the turned tool itself, so that R1 R2 p meets q to rounding even near the cone's edge.
    const std::optional<double> first = angleAbout(u1, r2 * p, q);
    out.push_back({first ? radToDeg(*first) : freeFirstDeg, radToDeg(*second)});
    if (g == 0.0) break;
  }
  return out;
}

Vec3 headLinear(const GcodeMachine& m, const Vec3& tip, const std::array<double, 2>& rotaryDeg)
{
  const Mat3 r1 = turn(m.rotary[0].about, rotaryDeg[0]);
  const Mat3 r2 = turn(m.rotary[1].about, rotaryDeg[1]);
  return tip - r1 * (m.firstToSecond + r2 * m.secondToTip);
}

std::vector<HeadAxes> solveHeadPath(const GcodeMachine& m, const std::vector<HeadPose>& poses,
                                    const std::function<std::string(size_t)>& poseName,
                                    double uprightToleranceDeg)
{
  const double uprightCos = std::cos(degToRad(uprightToleranceDeg));
  std::vector<HeadAxes> out(poses.size());
  std::array<double, 2> previous{0.0, 0.0};  // the first pose takes the branch nearest home
  for (size_t i = 0; i < poses.size(); ++i) {
    HeadPose pose = poses[i];
    pose.axis.normalize();
    if (uprightToleranceDeg > 0.0 && pose.axis.dot(m.toolDirection) >= uprightCos)
      pose.axis = m.toolDirection;
    const auto branches = headOrientations(m, pose.axis, previous[0]);
    if (branches.empty())
      throw InputError(
          poseName(i) + ": the head cannot point the torch along " + vecText(pose.axis.normalized()),
          "tilt the torch less (the plan's build direction or tool tilt), or use a machine whose "
          "rotary axes reach that direction");
    std::optional<std::array<double, 2>> best;
    double bestCost = 0.0;
    std::string refusal;
    for (const auto& b : branches) {
      std::array<double, 2> v{};
      bool inside = true;
      for (size_t k = 0; k < 2 && inside; ++k) {
        const RotaryAxis& a = m.rotary[k];
        const std::optional<double> t = nearestTurn(b[k], previous[k], a.minDeg, a.maxDeg);
        if (!t) {
          inside = false;
          if (refusal.empty())
            refusal = a.letter + " = " + roundedText(b[k], 3) +
                      " deg (or a whole turn from it), outside its limits " + roundedText(a.minDeg, 3) +
                      " .. " + roundedText(a.maxDeg, 3) + " deg";
        } else {
          v[k] = *t;
        }
      }
      if (!inside) continue;
      const double cost = std::abs(v[0] - previous[0]) + std::abs(v[1] - previous[1]);
      if (!best || cost < bestCost) {
        best = v;
        bestCost = cost;
      }
    }
    if (!best)
      throw InputError(
          poseName(i) + ": the torch axis " + vecText(pose.axis.normalized()) + " needs " + refusal,
          "widen the axis' limits in the machine file if the head allows it, tilt the torch less (the "
          "plan's build direction or tool tilt), or hold a slight lean upright (upright_tolerance)");
    HeadAxes& axes = out[i];
    axes.rotaryDeg = *best;
    axes.linear = headLinear(m, pose.tip + m.partOrigin, *best);
    for (size_t k = 0; k < 3; ++k) {
      const LinearAxis& a = m.linear[k];
      const double v = axes.linear[static_cast<Eigen::Index>(k)];
      if (v < a.minMm - kLimitSlackMm || v > a.maxMm + kLimitSlackMm)
        throw InputError(poseName(i) + ": " + a.letter + " = " + roundedText(v, 3) +
                             " mm is outside its limits " + roundedText(a.minMm, 3) + " .. " +
                             roundedText(a.maxMm, 3) + " mm",
                         "move the part within the machine's travel (part_origin_mm in the machine file)");
    }
    previous = *best;
  }
  return out;
}

}  // namespace spira
