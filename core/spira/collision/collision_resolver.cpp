#include "spira/collision/collision_resolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "spira/base/error.h"
#include "spira/collision/tilt_about_tangent.h"
#include "spira/collision/tilt_ramp.h"
#include "spira/collision/tilt_search.h"

namespace spira {

namespace {

constexpr size_t kBlock = 2048;  // points per parallel block between cancellation checks
const double kUnknown = std::numeric_limits<double>::quiet_NaN();

// Runs body(k) for k in [0, count) on all cores, checking for cancellation between blocks.
template <class Body>
void parallelBlocks(size_t count, Progress& progress, double from, double to, const char* stage, Body body)
{
  for (size_t begin = 0; begin < count; begin += kBlock) {
    progress.checkCancel();
    const size_t end = std::min(count, begin + kBlock);
    tbb::parallel_for(tbb::blocked_range<size_t>(begin, end, 16), [&](const tbb::blocked_range<size_t>& r) {
      for (size_t k = r.begin(); k != r.end(); ++k) body(k);
    });
    progress.report(from + (to - from) * static_cast<double>(end) / static_cast<double>(count), stage);
  }
}

// The clearing tilt magnitude per point and sign (NaN: not searched yet, +inf: none).
struct Options {
  std::vector<double> plus, minus;
  double& of(size_t i, int sign) { return sign > 0 ? plus[i] : minus[i]; }
  double of(size_t i, int sign) const { return sign > 0 ? plus[i] : minus[i]; }
};

// Signed requirement from the two options: the smaller magnitude (+ on ties), 0 when neither exists.
double smallerOption(const Options& opt, size_t i)
{
  const double p = opt.plus[i], m = opt.minus[i];
  const bool hasP = std::isfinite(p), hasM = std::isfinite(m);
  if (hasP && (!hasM || p <= m)) return p;
  if (hasM) return -m;
  return 0.0;
}

// Makes every requirement in [begin, end) take one sign: the one that clears the most of them, then
// the smaller largest tilt. A requirement impossible in that sign is dropped (left to the final check).
void unifySign(std::vector<double>& required, const Options& opt, size_t begin, size_t end)
{
  int bestSign = 1;
  size_t bestCount = 0;
  double bestCost = std::numeric_limits<double>::infinity();
  for (const int sign : {1, -1}) {
    size_t count = 0;
    double cost = 0.0;
    for (size_t i = begin; i < end; ++i) {
      if (required[i] == 0.0 || !std::isfinite(opt.of(i, sign))) continue;
      ++count;
      cost = std::max(cost, opt.of(i, sign));
    }
    if (count > bestCount || (count == bestCount && cost < bestCost)) {
      bestSign = sign;
      bestCount = count;
      bestCost = cost;
    }
  }
  for (size_t i = begin; i < end; ++i) {
    if (required[i] == 0.0) continue;
    const double m = opt.of(i, bestSign);
    required[i] = std::isfinite(m) ? bestSign * m : 0.0;
  }
}

// The tilt profile: each sign's requirements ramped at maxStep, with ramps of opposite signs that
// would overlap first merged into one sign (a torch cannot swing through zero faster than the ramp).
std::vector<double> signedRamp(std::vector<double>& required, const Options& opt, double maxStep)
{
  const size_t n = required.size();
  std::vector<double> plus(n), minus(n);
  for (size_t round = 0; round <= n; ++round) {
    for (size_t i = 0; i < n; ++i) {
      plus[i] = std::max(required[i], 0.0);
      minus[i] = std::max(-required[i], 0.0);
    }
    const std::vector<double> P = rampEnvelope(plus, maxStep), N = rampEnvelope(minus, maxStep);
    bool changed = false;
    for (size_t i = 0; i < n;) {
      if (P[i] == 0.0 && N[i] == 0.0) {
        ++i;
        continue;
      }
      size_t end = i;
      bool pos = false, neg = false;
      for (; end < n && (P[end] > 0.0 || N[end] > 0.0); ++end) {
        pos = pos || required[end] > 0.0;
        neg = neg || required[end] < 0.0;
      }
      if (pos && neg) {
        unifySign(required, opt, i, end);
        changed = true;
      }
      i = end;
    }
    if (!changed) {
      std::vector<double> tilt(n);
      for (size_t i = 0; i < n; ++i) tilt[i] = P[i] - N[i];
      return tilt;
    }
  }
  throw InternalError("collision resolution: the tilt signs did not settle");
}

// +1 or -1 per point so that side[i] * (t x b)_i keeps its direction along the path. Tilts are
// ramped in this aligned sense: where the travel reverses (t and n flip, b stays) the same torch
// axis needs the opposite tilt sign, and a ramp on raw signs would swing the torch there.
std::vector<int> alignedSides(const Trajectory& plan)
{
  std::vector<int> side(plan.size(), 1);
  Vec3 previous = Vec3::Zero();
  for (size_t i = 0; i < plan.size(); ++i) {
    const TrajectoryPoint& p = plan.points[i];
    const Vec3 lean = p.tangent.cross(p.build);
    if (i > 0) side[i] = lean.dot(previous) < 0.0 ? -side[i - 1] : side[i - 1];
    if (lean.squaredNorm() > 0.0) previous = lean;
  }
  return side;
}

}  // namespace

size_t CollisionResolution::collisionCount() const
{
  return static_cast<size_t>(std::count_if(hits.begin(), hits.end(), [](unsigned h) { return h != 0; }));
}

CollisionResolution resolveTorchCollisions(const Trajectory& plan, const TorchCollisionChecker& checker,
                                           const ResolveSettings& settings, Progress& progress)
{
  validateResolveSettings(settings);
  const size_t n = plan.size();
  if (checker.size() != n)
    throw InternalError("collision resolution: the checker holds " + std::to_string(checker.size()) +
                        " points, the plan " + std::to_string(n));
  CollisionResolution out;
  out.hits.assign(n, 0);
  parallelBlocks(n, progress, 0.0, 0.6, "collision check", [&](size_t i) { out.hits[i] = checker.hits(i); });

  // Options, requirements and the ramp are in aligned tilts (see alignedSides); the tilt about t at
  // point i is side[i] times the aligned one.
  const std::vector<int> side = alignedSides(plan);
  Options opt{std::vector<double>(n, kUnknown), std::vector<double>(n, kUnknown)};
  std::vector<size_t> work;
  for (size_t i = 0; i < n; ++i)
    if (out.hits[i] != 0) work.push_back(i);
  parallelBlocks(work.size(), progress, 0.6, 0.8, "collision resolution", [&](size_t k) {
    const size_t i = work[k];
    opt.plus[i] = clearingTilt(checker, i, side[i], 0.0, settings);
    opt.minus[i] = clearingTilt(checker, i, -side[i], 0.0, settings);
  });
  std::vector<double> required(n, 0.0);
  for (const size_t i : work) required[i] = smallerOption(opt, i);

  // A ramp may tilt a clear neighbour into something: such points get their own requirement,
  // searched onwards from the tilt the ramp gave them, and the profile is ramped again.
  std::vector<char> exhausted(n, 0);
  std::vector<double> aligned;
  const auto tiltAt = [&](size_t i) { return side[i] * aligned[i]; };
  for (int pass = 0; pass < settings.maxPasses; ++pass) {
    aligned = signedRamp(required, opt, settings.maxTiltChangeRad);
    std::vector<size_t> tilted;
    for (size_t i = 0; i < n; ++i)
      if (aligned[i] != 0.0 && !exhausted[i]) tilted.push_back(i);
    std::vector<char> bad(tilted.size(), 0);
    const double at = 0.8 + 0.15 * pass / settings.maxPasses;
    parallelBlocks(tilted.size(), progress, at, at, "collision resolution",
                   [&](size_t k) { bad[k] = checker.collides(tilted[k], tiltAt(tilted[k])); });
    std::vector<size_t> fix;
    for (size_t k = 0; k < tilted.size(); ++k)
      if (bad[k]) fix.push_back(tilted[k]);
    if (fix.empty()) break;
    parallelBlocks(fix.size(), progress, at, at, "collision resolution", [&](size_t k) {
      const size_t i = fix[k];
      const int sign = aligned[i] > 0.0 ? 1 : -1;
      opt.of(i, sign) = clearingTilt(checker, i, sign * side[i], std::abs(aligned[i]), settings);
      if (std::isnan(opt.of(i, -sign)))
        opt.of(i, -sign) = clearingTilt(checker, i, -sign * side[i], 0.0, settings);
    });
    for (const size_t i : fix) {
      const int sign = aligned[i] > 0.0 ? 1 : -1;
      if (std::isfinite(opt.of(i, sign))) {
        required[i] = sign * opt.of(i, sign);
      } else if (std::isfinite(opt.of(i, -sign))) {
        required[i] = -sign * opt.of(i, -sign);
      } else {
        exhausted[i] = 1;
      }
    }
  }

  std::vector<double> tilt(n);
  for (size_t i = 0; i < n; ++i) tilt[i] = tiltAt(i);
  std::vector<size_t> check;
  for (size_t i = 0; i < n; ++i)
    if (tilt[i] != 0.0 || out.hits[i] != 0) check.push_back(i);
  std::vector<char> stillBad(check.size(), 0);
  parallelBlocks(check.size(), progress, 0.95, 1.0, "collision verification",
                 [&](size_t k) { stillBad[k] = checker.collides(check[k], tilt[check[k]]); });
  for (size_t k = 0; k < check.size(); ++k)
    if (stillBad[k]) out.unresolved.push_back(check[k]);

  out.trajectory = plan;
  for (size_t i = 0; i < n; ++i) out.trajectory.points[i] = tiltAboutTangent(plan.points[i], tilt[i]);
  out.trajectory.extra["torch_tilt"] = tilt;
  out.tiltRad = std::move(tilt);
  progress.report(1.0, "collision resolution");
  return out;
}

}  // namespace spira
