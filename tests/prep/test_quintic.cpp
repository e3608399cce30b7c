#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "prep_shapes.h"
#include "spira/base/progress.h"
#include "spira/prep/quintic.h"
#include "spira/prep/quintic_path.h"
#include "spira/prep/smoothing.h"

using namespace spira;
using namespace spira::test;

namespace {

Vec3 randomVec(std::mt19937& rng)
{
  std::uniform_real_distribution<double> d(-10.0, 10.0);
  return Vec3(d(rng), d(rng), d(rng));
}

Trajectory halfCircle(double R, const std::vector<double>& angles)
{
  Trajectory tr;
  for (double a : angles) tr.points.push_back(circlePoint(R, a));
  return tr;
}

}  // namespace

// A-T1: the six boundary conditions of the quintic Hermite, for random data.
TEST(Quintic, HermiteMatchesValueAndTwoDerivativesAtBothEnds)
{
  std::mt19937 rng(7);
  for (int trial = 0; trial < 50; ++trial) {
    const Vec3 p0 = randomVec(rng), v0 = randomVec(rng), a0 = randomVec(rng);
    const Vec3 p1 = randomVec(rng), v1 = randomVec(rng), a1 = randomVec(rng);
    const Quintic3 q = Quintic3::hermite(p0, v0, a0, p1, v1, a1);
    EXPECT_LT((q.value(0.0) - p0).norm(), 1e-9);
    EXPECT_LT((q.derivative(0.0) - v0).norm(), 1e-9);
    EXPECT_LT((q.secondDerivative(0.0) - a0).norm(), 1e-9);
    EXPECT_LT((q.value(1.0) - p1).norm(), 1e-9);
    EXPECT_LT((q.derivative(1.0) - v1).norm(), 1e-9);
    EXPECT_LT((q.secondDerivative(1.0) - a1).norm(), 1e-9);
  }
}

// On a curve that is itself a parabola in the chord-length-like parameter, the three-point rule is
// exact at every node: X(t) = c + d t + e t^2 has X' = d + 2 e t, X'' = 2 e.
TEST(Quintic, ParabolaRuleIsExactOnAParabola)
{
  const Vec3 c(1, -2, 3), d(0.5, 0.25, -1), e(0.1, -0.3, 0.2);
  const auto x = [&](double t) { return Vec3(c + d * t + e * t * t); };
  const double l01 = 0.7, l12 = 2.3;
  const double nodes[3] = {0.0, l01, l01 + l12};
  for (int node = 0; node < 3; ++node) {
    const ParabolaDerivatives pd = parabolaDerivatives(x(nodes[0]), x(nodes[1]), x(nodes[2]), l01, l12, node);
    EXPECT_LT((pd.first - (d + 2.0 * e * nodes[node])).norm(), 1e-12) << node;
    EXPECT_LT((pd.second - 2.0 * e).norm(), 1e-12) << node;
  }
  // The centred closed form printed in A.2.1.
  const Vec3 m0 = x(0.0), m1 = x(l01), m2 = x(l01 + l12);
  const Vec3 printed =
      -l12 / (l01 * (l01 + l12)) * m0 + (l12 - l01) / (l01 * l12) * m1 + l01 / (l12 * (l01 + l12)) * m2;
  EXPECT_LT((parabolaDerivatives(m0, m1, m2, l01, l12, 1).first - printed).norm(), 1e-12);
}

// Half circle R = 50 through 62 irregular samples. The quintic stays within 0.01 mm of the exact
// circle (a quick computation of the same fit gives 0.0024 mm, the chords 0.369 mm), the chords do not.
TEST(Quintic, HalfCircleFromIrregularSamplesIsReproduced)
{
  const double R = 50.0;
  const std::vector<double> angles = irregularAngles(62, 81);
  const Trajectory tr = halfCircle(R, angles);
  const QuinticPath path(tr, true, degToRad(60.0));
  ASSERT_EQ(path.intervals(), 61u);

  double quinticDev = 0.0, chordDev = 0.0, maxGap = 0.0;
  for (size_t k = 0; k < path.intervals(); ++k) {
    maxGap = std::max(maxGap, angles[k + 1] - angles[k]);
    // The chord's worst point is its middle: R (1 - cos(gap / 2)) inside the circle.
    chordDev = std::max(chordDev, R * (1.0 - std::cos(0.5 * (angles[k + 1] - angles[k]))));
    for (int j = 0; j <= 200; ++j) {
      const TrajectoryPoint p = path.point(k, j / 200.0);
      quinticDev = std::max(quinticDev, std::abs(p.position.norm() - R));
      EXPECT_NEAR(p.position.z(), 0.0, 1e-12);
    }
  }
  std::printf("half circle, 62 irregular points (max gap %.3f rad): quintic %.5f mm, chords %.4f mm\n",
              maxGap, quinticDev, chordDev);
  EXPECT_GT(chordDev, 0.1);  // the sample is irregular enough for the chords to be far off
  EXPECT_LT(quinticDev, 0.01);
  EXPECT_LT(quinticDev, chordDev / 20.0);
}

// The frame vectors are smoothed by the same rule and made orthonormal again: on the half circle the
// smoothed frame agrees with the exact frame at the smoothed point's angle.
TEST(Quintic, FramesFollowTheCircle)
{
  const double R = 50.0;
  const Trajectory tr = halfCircle(R, irregularAngles(62, 81));
  const QuinticPath path(tr, true, degToRad(60.0));
  double worst = 0.0;
  for (size_t k = 0; k < path.intervals(); ++k) {
    for (int j = 0; j < 20; ++j) {
      const TrajectoryPoint p = path.point(k, j / 20.0);
      const TrajectoryPoint exact = circlePoint(R, std::atan2(p.position.y(), p.position.x()));
      EXPECT_NEAR(p.normal.norm(), 1.0, 1e-12);
      EXPECT_NEAR(p.normal.dot(p.tangent), 0.0, 1e-12);
      EXPECT_LT((p.normal.cross(p.tangent) - p.build).norm(), 1e-12);
      for (const auto& [u, v] : {std::pair{p.normal, exact.normal}, {p.tangent, exact.tangent}})
        worst = std::max(worst, std::atan2(u.cross(v).norm(), u.dot(v)));
    }
  }
  EXPECT_LT(worst, 1e-3);  // rad
}

// The sampled quintic: every source point is a sample, samples keep within resampleTolerance of the
// circle between them (chord of the samples), and no gap exceeds maxSpacing.
TEST(Quintic, SmoothedSamplesKeepChordToleranceAndSourcePoints)
{
  const double R = 50.0;
  const Trajectory tr = halfCircle(R, irregularAngles(62, 81));
  PrepParams params;
  params.resampleTolerance = 0.005;
  params.maxSpacing = 3.0;
  NullProgress progress;
  const SmoothedSamples s = smoothTrajectory(tr, params, progress);
  ASSERT_EQ(s.samples.size(), s.sourceParam.size());
  size_t sourceHits = 0;
  for (size_t j = 0; j < s.samples.size(); ++j) {
    const double param = s.sourceParam[j];
    if (param == std::floor(param)) {
      ++sourceHits;
      EXPECT_LT((s.samples.points[j].position - tr.points[static_cast<size_t>(param)].position).norm(),
                1e-12);
    }
    if (j == 0) continue;
    const Vec3& a = s.samples.points[j - 1].position;
    const Vec3& b = s.samples.points[j].position;
    EXPECT_LE((b - a).norm(), params.maxSpacing + 1e-9);
    // The chord's sagitta on the circle, plus the quintic's own distance from the circle.
    const double sagitta = R - std::sqrt(R * R - 0.25 * (b - a).squaredNorm());
    EXPECT_LT(sagitta, params.resampleTolerance * 1.5 + 0.01);
  }
  EXPECT_EQ(sourceHits, tr.size());
  EXPECT_GT(s.maxOffset, 0.1);  // the smoothing moved samples off the chords by about their sagitta
}

// A sharp corner stays a corner: both intervals are straight lines here, so the quintic must not bulge.
TEST(Quintic, CornerIsKept)
{
  Trajectory tr;
  for (int i = 0; i <= 10; ++i) {
    TrajectoryPoint p = circlePoint(1.0, 0.0);
    p.position = i <= 5 ? Vec3(i, 0, 0) : Vec3(5, i - 5, 0);
    tr.points.push_back(p);
  }
  const QuinticPath path(tr, true, degToRad(60.0));
  for (size_t k = 0; k < path.intervals(); ++k) {
    for (int j = 0; j <= 10; ++j) {
      const Vec3 p = path.point(k, j / 10.0).position;
      const double off = k < 5 ? std::abs(p.y()) : std::abs(p.x() - 5.0);
      EXPECT_LT(off, 1e-12) << k << " " << j;
    }
  }
}
