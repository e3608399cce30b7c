#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "prep_shapes.h"
#include "spira/base/error.h"
#include "spira/base/progress.h"
#include "spira/prep/prepare_trajectory.h"

using namespace spira;
using namespace spira::test;

namespace {

// The prepared path read back at every ORIGINAL point: the prepared point k + u lies at source arc
// position s_k + u L_k; an original point at arc position s falls in the prepared segment around s,
// where the robot is on the straight segment and the channels ramp linearly in s.
struct ReadBack {
  double chord = 0.0;  // max distance of an original point from its prepared segment
  double height = 0.0, travelSpeed = 0.0, wireFeed = 0.0, extra = 0.0;  // max |interpolated - original|
  double angle = 0.0;                                                   // max frame angle, rad
};

Eigen::Quaterniond quat(const TrajectoryPoint& p)
{
  Mat3 r;
  r << p.normal, p.tangent, p.build;
  return Eigen::Quaterniond(r);
}

ReadBack readBack(const Trajectory& src, const PreparedTrajectory& prep, const std::string& extra = {})
{
  std::vector<double> s(src.size(), 0.0);
  for (size_t k = 1; k < src.size(); ++k)
    s[k] = s[k - 1] + (src.points[k].position - src.points[k - 1].position).norm();
  std::vector<double> out;
  for (double param : prep.sourceParam) {
    const size_t k = std::min(static_cast<size_t>(param), src.size() - 1);
    out.push_back(k + 1 < src.size() ? s[k] + (param - k) * (s[k + 1] - s[k]) : s[k]);
  }
  ReadBack r;
  const auto& o = prep.trajectory.points;
  size_t m = 0;
  for (size_t k = 0; k < src.size(); ++k) {
    while (m + 2 < o.size() && out[m + 1] <= s[k]) ++m;
    const double f =
        out[m + 1] > out[m] ? std::clamp((s[k] - out[m]) / (out[m + 1] - out[m]), 0.0, 1.0) : 0.0;
    const auto lerp = [&](double a, double b) { return a + f * (b - a); };
    const TrajectoryPoint& p = src.points[k];
    const Vec3 ab = o[m + 1].position - o[m].position;
    const double t = ab.squaredNorm() > 0
                         ? std::clamp((p.position - o[m].position).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                         : 0.0;
    r.chord = std::max(r.chord, (p.position - (o[m].position + t * ab)).norm());
    r.height = std::max(r.height, std::abs(lerp(o[m].height, o[m + 1].height) - p.height));
    r.travelSpeed =
        std::max(r.travelSpeed, std::abs(lerp(o[m].travelSpeed, o[m + 1].travelSpeed) - p.travelSpeed));
    r.wireFeed = std::max(r.wireFeed, std::abs(lerp(o[m].wireFeed, o[m + 1].wireFeed) - p.wireFeed));
    r.angle = std::max(r.angle, quat(o[m]).slerp(f, quat(o[m + 1])).angularDistance(quat(p)));
    if (!extra.empty()) {
      const auto& e = prep.trajectory.extra.at(extra);
      r.extra = std::max(r.extra, std::abs(lerp(e[m], e[m + 1]) - src.extra.at(extra)[k]));
    }
  }
  return r;
}

}  // namespace

// A helix on a cylinder with a modulated deposit height, travel speed and wire feed: the prepared path
// has far fewer points, and read back at every original point it is within every tolerance.
TEST(Prepare, ModulatedHelixKeepsEveryToleranceAtOriginalPoints)
{
  Trajectory src = modulatedHelix(50.0, 2.0, 3.0, 0.8, 0.5, 10.0);
  std::vector<double> weave;
  for (const auto& p : src.points)
    weave.push_back(0.5 * std::sin(std::atan2(p.position.y(), p.position.x()) * 7.0));
  src.extra["weave"] = weave;
  PrepParams params;
  params.chordTolerance = 0.05;
  params.heightTolerance = 0.02;
  params.travelSpeedTolerance = 0.1;
  params.wireFeedTolerance = 1.0;
  params.extraTolerances["weave"] = 0.02;
  NullProgress progress;
  const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
  const PrepReport& rep = prep.report;
  std::printf("helix %zu points -> %zu samples -> %zu prepared, chord %.4f mm, height %.4f mm\n",
              rep.pointsIn, rep.samples, rep.pointsOut, rep.maxChordDeviation,
              rep.maxChannelDeviation.at("height"));

  EXPECT_EQ(rep.pointsIn, src.size());
  EXPECT_EQ(rep.pointsOut, prep.trajectory.size());
  EXPECT_LT(rep.pointsOut * 2, rep.pointsIn);
  ASSERT_EQ(prep.sourceIndex.size(), prep.trajectory.size());
  EXPECT_EQ(rep.spacingOverrides, 0u);

  const ReadBack rb = readBack(src, prep, "weave");
  EXPECT_LE(rb.chord, params.chordTolerance + 1e-9);
  EXPECT_LE(rb.height, params.heightTolerance + 1e-9);
  EXPECT_LE(rb.travelSpeed, params.travelSpeedTolerance + 1e-9);
  EXPECT_LE(rb.wireFeed, params.wireFeedTolerance + 1e-9);
  EXPECT_LE(rb.extra, 0.02 + 1e-9);
  EXPECT_LE(rb.angle, params.orientationTolerance + 1e-9);
  EXPECT_LE(rep.maxChordDeviation, params.chordTolerance + 1e-12);
  EXPECT_LE(rep.maxChannelDeviation.at("height"), params.heightTolerance + 1e-12);
  // The modulation survives: the prepared heights still span the planned range.
  double hMin = 1e9, hMax = -1e9;
  for (const auto& p : prep.trajectory.points)
    hMin = std::min(hMin, p.height), hMax = std::max(hMax, p.height);
  EXPECT_GT(hMax, 2.5 - params.heightTolerance - 1e-9);
  EXPECT_LT(hMin, 1.5 + params.heightTolerance + 1e-9);
  EXPECT_LE(rep.maxSegment, params.maxSpacing + 1e-9);
  EXPECT_GE(rep.minSegment, params.minSpacing - 1e-9);
  // First and last point stay.
  EXPECT_LT((prep.trajectory.points.front().position - src.points.front().position).norm(), 1e-12);
  EXPECT_LT((prep.trajectory.points.back().position - src.points.back().position).norm(), 1e-12);
  EXPECT_EQ(prep.sourceIndex.back(), src.size() - 1);
}

// The height tolerance is what keeps the points: the same helix without modulation needs fewer.
TEST(Prepare, ModulationCostsPointsNotAccuracy)
{
  NullProgress progress;
  PrepParams params;
  params.travelSpeedTolerance = 10.0;
  params.wireFeedTolerance = 100.0;
  const size_t flat =
      prepareTrajectory(modulatedHelix(50.0, 2.0, 2.0, 0.8, 0.0, 10.0), params, progress).report.pointsOut;
  const size_t modulated =
      prepareTrajectory(modulatedHelix(50.0, 2.0, 2.0, 0.8, 0.5, 10.0), params, progress).report.pointsOut;
  params.heightTolerance = 1.0;
  const size_t loose =
      prepareTrajectory(modulatedHelix(50.0, 2.0, 2.0, 0.8, 0.5, 10.0), params, progress).report.pointsOut;
  EXPECT_GT(modulated, flat + flat / 4);
  EXPECT_EQ(loose, flat);
  // Chord-limited: a chord of sagitta 0.05 mm on R = 50 is sqrt(8 R tol) = 4.47 mm long, so two turns
  // (628 mm) need at least 141 segments.
  EXPECT_GE(flat, 141u);
  EXPECT_LE(flat, 200u);
}

// A straight line collapses to its end points when nothing limits the spacing, and to equal pieces of
// at most maxSpacing otherwise.
TEST(Prepare, StraightLineCollapses)
{
  const Trajectory src = straightLine(100.0, 101);
  NullProgress progress;
  PrepParams params;
  params.maxSpacing = 1000.0;
  const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
  ASSERT_EQ(prep.trajectory.size(), 2u);
  EXPECT_EQ(prep.sourceIndex[0], 0u);
  EXPECT_EQ(prep.sourceIndex[1], 100u);
  EXPECT_LT(prep.report.maxChordDeviation, 1e-9);

  params.maxSpacing = 5.0;
  const PreparedTrajectory pieces = prepareTrajectory(src, params, progress);
  EXPECT_EQ(pieces.trajectory.size(), 21u);
  EXPECT_NEAR(pieces.report.maxSegment, 5.0, 1e-9);
  EXPECT_NEAR(pieces.report.minSegment, 5.0, 1e-9);
}

// Arc switches are kept exactly, on both sides; revolution starts when asked.
TEST(Prepare, ArcSwitchesAndRevolutionStartsAreKept)
{
  Trajectory src = modulatedHelix(50.0, 2.0, 2.0, 0.8, 0.0, 1.0);
  for (size_t k = 200; k < 230; ++k) src.points[k].arcOn = false;
  NullProgress progress;
  PrepParams params;
  params.keepRevolutionStarts = true;
  params.travelSpeedTolerance = 10.0;
  params.wireFeedTolerance = 100.0;
  const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
  std::vector<double> kept(prep.sourceParam);
  const auto has = [&](double k) { return std::find(kept.begin(), kept.end(), k) != kept.end(); };
  for (size_t k : {199u, 200u, 229u, 230u}) EXPECT_TRUE(has(static_cast<double>(k))) << k;
  for (size_t k = 1; k < src.size(); ++k) {
    if (src.points[k].revolution != src.points[k - 1].revolution) {
      EXPECT_TRUE(has(static_cast<double>(k))) << k;
    }
  }
  for (size_t m = 0; m < prep.trajectory.size(); ++m) {
    const size_t k = static_cast<size_t>(prep.sourceParam[m]);
    EXPECT_EQ(prep.trajectory.points[m].arcOn, src.points[k].arcOn) << m;
  }
}

// The greedy skip on noisy data (A-T4): the point count falls as the chord tolerance grows, close to
// the count an exact circle needs, arc / sqrt(8 R tol).
TEST(Prepare, PointCountFollowsChordTolerance)
{
  const double R = 50.0;
  Trajectory src;
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> noise(-0.001, 0.001);
  const int n = 503;
  for (int i = 0; i < n; ++i) {
    TrajectoryPoint p = circlePoint(R + noise(rng), 0.5 * kPi * i / (n - 1));
    src.points.push_back(p);
  }
  NullProgress progress;
  PrepParams params;
  params.smooth = false;
  params.maxSpacing = 1000.0;
  params.minSpacing = 0.0;
  params.orientationTolerance = kPi;
  size_t previous = src.size();
  for (double tol : {0.005, 0.01, 0.06}) {
    params.chordTolerance = tol;
    const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
    const double ideal = 0.5 * kPi * R / std::sqrt(8.0 * R * tol);
    std::printf("IT_C %.3f mm: %zu points (exact circle %.1f segments)\n", tol, prep.trajectory.size(),
                ideal);
    EXPECT_LT(prep.trajectory.size(), previous);
    EXPECT_GT(prep.trajectory.size(), ideal);
    EXPECT_LT(prep.trajectory.size(), 1.6 * ideal + 2);
    EXPECT_LE(readBack(src, prep).chord, tol + 1e-9);
    previous = prep.trajectory.size();
  }
}

TEST(Prepare, RejectsBadInput)
{
  Trajectory src = straightLine(10.0, 11);
  NullProgress progress;
  PrepParams params;
  params.minSpacing = 6.0;
  EXPECT_THROW(prepareTrajectory(src, params, progress), InputError);
  params = PrepParams{};
  params.chordTolerance = -1.0;
  EXPECT_THROW(prepareTrajectory(src, params, progress), InputError);
  params = PrepParams{};
  src.extra["dwell"] = {1.0, 2.0};
  EXPECT_THROW(prepareTrajectory(src, params, progress), InputError);
}

TEST(Prepare, TinyInputs)
{
  NullProgress progress;
  EXPECT_EQ(prepareTrajectory(Trajectory{}, PrepParams{}, progress).trajectory.size(), 0u);
  Trajectory one;
  one.points.push_back(circlePoint(10.0, 0.3));
  EXPECT_EQ(prepareTrajectory(one, PrepParams{}, progress).trajectory.size(), 1u);
}

// A sparse helix (6 mm between points: the chords sag 0.09 mm) prepared with smoothing lies within
// the chord tolerance of the EXACT helix, which the source polyline does not.
TEST(Prepare, SparseHelixIsRestoredBySmoothing)
{
  const double R = 50.0, pitch = 2.0;
  const Trajectory src = modulatedHelix(R, pitch, 1.0, 6.0, 0.0, 1.0);
  NullProgress progress;
  PrepParams params;
  params.travelSpeedTolerance = 10.0;
  params.wireFeedTolerance = 100.0;
  const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
  EXPECT_GT(prep.report.samples, src.size());
  EXPECT_GT(prep.report.maxSmoothingOffset, 0.05);
  // Distance of the exact helix from a polyline, segment by segment in angle (both unwrap from 0).
  const auto offHelix = [&](const Trajectory& poly) {
    std::vector<double> angle;
    for (const auto& p : poly.points) angle.push_back(p.position.z() / pitch * 2.0 * kPi);
    double worst = 0.0;
    size_t m = 0;
    for (int i = 0; i <= 20000; ++i) {
      const double a = 2.0 * kPi * i / 20000;
      const Vec3 q(R * std::cos(a), R * std::sin(a), pitch * a / (2.0 * kPi));
      while (m + 2 < angle.size() && angle[m + 1] <= a) ++m;
      const Vec3 ab = poly.points[m + 1].position - poly.points[m].position;
      const double f = std::clamp((q - poly.points[m].position).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      worst = std::max(worst, (q - poly.points[m].position - f * ab).norm());
    }
    return worst;
  };
  const double sourceOff = offHelix(src), preparedOff = offHelix(prep.trajectory);
  std::printf("sparse helix: source chords %.4f mm off the helix, prepared %.4f mm (%zu -> %zu points)\n",
              sourceOff, preparedOff, src.size(), prep.trajectory.size());
  EXPECT_GT(sourceOff, 0.08);
  EXPECT_LT(preparedOff, params.chordTolerance + params.resampleTolerance + 0.005);
  EXPECT_LE(prep.report.maxSegment, params.maxSpacing + 1e-9);
}

// Near-duplicate points are not emitted even where a channel jumps between them: the minimum spacing
// wins, and the report says what that cost instead of hiding it.
TEST(Prepare, MinimumSpacingWinsAndIsReported)
{
  Trajectory src = straightLine(20.0, 21);
  TrajectoryPoint extra = src.points[10];
  extra.position.x() += 0.1;
  src.points.insert(src.points.begin() + 11, extra);
  for (size_t k = 11; k < src.size(); ++k) src.points[k].travelSpeed = 12.0;  // 10 -> 12 mm/s over 0.1 mm
  NullProgress progress;
  PrepParams params;
  params.minSpacing = 0.5;
  const PreparedTrajectory prep = prepareTrajectory(src, params, progress);
  EXPECT_GE(prep.report.minSegment, params.minSpacing - 1e-9);
  EXPECT_GE(prep.report.spacingOverrides, 1u);
  EXPECT_GT(prep.report.maxChannelDeviation.at("travelSpeed"), params.travelSpeedTolerance);
  // Without the minimum the step is kept exactly.
  params.minSpacing = 0.0;
  const PreparedTrajectory exact = prepareTrajectory(src, params, progress);
  EXPECT_NEAR(exact.report.minSegment, 0.1, 1e-9);
  EXPECT_LE(exact.report.maxChannelDeviation.at("travelSpeed"), params.travelSpeedTolerance);
  EXPECT_EQ(exact.report.spacingOverrides, 0u);
}
