#include "skeleton_fit.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"

namespace spira {

namespace {

double horizontal(const Vec3& a, const Vec3& b)
{
  return std::hypot(a.x() - b.x(), a.y() - b.y());
}

// Weighted least squares of x and y against z; a flat set (no spread in z) gives the weighted mean
// and no slope.
struct LinearFit {
  double sw = 0, sz = 0, szz = 0;
  Eigen::Vector2d sp = Eigen::Vector2d::Zero(), szp = Eigen::Vector2d::Zero();

  void add(const Vec3& p, double w)
  {
    sw += w;
    sz += w * p.z();
    szz += w * p.z() * p.z();
    sp += w * Eigen::Vector2d(p.x(), p.y());
    szp += w * p.z() * Eigen::Vector2d(p.x(), p.y());
  }

  // Origin (at z = 0) and slope.
  std::pair<Eigen::Vector2d, Eigen::Vector2d> solve() const
  {
    const double meanZ = sz / sw;
    const double varZ = szz / sw - meanZ * meanZ;
    const Eigen::Vector2d meanP = sp / sw;
    if (!(varZ > 1e-12 * std::max(1.0, meanZ * meanZ))) return {meanP, Eigen::Vector2d::Zero()};
    const Eigen::Vector2d slope = (szp / sw - meanZ * meanP) / varZ;
    return {meanP - meanZ * slope, slope};
  }
};

}  // namespace

HeightFit fitChainByHeight(const Polyline& chain, double halfWidth)
{
  if (chain.size() < 2)
    throw InputError("the skeleton chain has fewer than two points", "check the part's skeleton");
  double z0 = chain.front().z(), z1 = chain.back().z();
  if (z0 > z1) std::swap(z0, z1);
  if (!(z1 > z0))
    throw InputError("the skeleton does not rise, so it gives no point per height",
                     "use the iso-value strategy (--strategy isovalue) for this part");
  HeightFit out;
  LinearFit whole;
  for (const Vec3& p : chain) whole.add(p, 1.0);
  const auto [origin, slope] = whole.solve();
  out.lineOrigin = Vec3(origin.x(), origin.y(), 0.0);
  out.lineSlope = Vec3(slope.x(), slope.y(), 0.0);

  // As many points as the chain has nodes: the fit neither thins nor pads the skeleton.
  const size_t n = std::max<size_t>(2, chain.size());
  const double h = std::max(halfWidth, 2.0 * (z1 - z0) / static_cast<double>(n));
  out.points.reserve(n);
  for (size_t k = 0; k < n; ++k) {
    const double z = z0 + (z1 - z0) * static_cast<double>(k) / static_cast<double>(n - 1);
    LinearFit local;
    for (const Vec3& p : chain) {
      const double u = std::abs(p.z() - z) / h;
      if (u >= 1.0) continue;
      const double w = 1.0 - u * u * u;  // tricube: near nodes count most, the window fades out
      local.add(p, w * w * w);
    }
    if (local.sw <= 0) {
      out.points.push_back(out.lineAt(z));
      continue;
    }
    const auto [o, s] = local.solve();
    out.points.emplace_back(o.x() + z * s.x(), o.y() + z * s.y(), z);
  }
  return out;
}

double largestOffsetFromVertical(const HeightFit& fit, const Vec3& centre, double z0, double z1)
{
  double worst = std::max(horizontal(fit.lineAt(z0), centre), horizontal(fit.lineAt(z1), centre));
  for (const Vec3& p : fit.points) worst = std::max(worst, horizontal(p, centre));
  return worst;
}

double largestOffsetFromLine(const HeightFit& fit)
{
  double worst = 0.0;
  for (const Vec3& p : fit.points) worst = std::max(worst, horizontal(p, fit.lineAt(p.z())));
  return worst;
}

}  // namespace spira
