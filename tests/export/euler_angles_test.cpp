// The controllers' angle conventions against hand-built rotations, plus round trips through
// the gimbal lock (B or P = +-90 degrees), compared as matrices.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "spira/base/units.h"
#include "spira/export/euler_angles.h"

namespace spira {
namespace {

Mat3 columns(const Vec3& x, const Vec3& y, const Vec3& z)
{
  Mat3 m;
  m.col(0) = x;
  m.col(1) = y;
  m.col(2) = z;
  return m;
}

Mat3 about(const Vec3& axis, double deg)
{
  return Eigen::AngleAxisd(degToRad(deg), axis).toRotationMatrix();
}

TEST(EulerAngles, KukaHomeFlangeIsB90)
{
  // tool0 at KUKA HOME (robots/README.md): Z forward (+X), X down: $POS_ACT A 0, B 90, C 0.
  const Mat3 r = columns(-Vec3::UnitZ(), Vec3::UnitY(), Vec3::UnitX());
  const KukaAbc abc = kukaAbcFromRotation(r);
  EXPECT_NEAR(radToDeg(abc.a), 0.0, 1e-12);
  EXPECT_NEAR(radToDeg(abc.b), 90.0, 1e-12);
  EXPECT_NEAR(radToDeg(abc.c), 0.0, 1e-12);
  EXPECT_NEAR((rotationFromKukaAbc({0.0, kPi / 2, 0.0}) - r).norm(), 0.0, 1e-15);
}

TEST(EulerAngles, FanucZeroJointsFlangeIsW180PMinus90)
{
  // tool0 at FANUC all-zero joints (robots/README.md): Z forward, X up = W 180, P -90, R 0.
  const Mat3 r = columns(Vec3::UnitZ(), -Vec3::UnitY(), Vec3::UnitX());
  EXPECT_NEAR((rotationFromFanucWpr({kPi, -kPi / 2, 0.0}) - r).norm(), 0.0, 1e-15);
  const FanucWpr wpr = fanucWprFromRotation(r);
  EXPECT_NEAR(radToDeg(wpr.p), -90.0, 1e-12);
  // At the lock only W - R is defined; the extraction puts it all in R (W = 0).
  EXPECT_NEAR(wpr.w, 0.0, 1e-15);
  EXPECT_NEAR((rotationFromFanucWpr(wpr) - r).norm(), 0.0, 1e-12);
}

TEST(EulerAngles, SingleAnglesTurnAboutTheDocumentedAxes)
{
  // KUKA A about Z, B about Y', C about X''; FANUC W about X, P about Y, R about Z.
  EXPECT_NEAR((rotationFromKukaAbc({degToRad(90), 0, 0}) * Vec3::UnitX() - Vec3::UnitY()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((rotationFromKukaAbc({0, degToRad(90), 0}) * Vec3::UnitZ() - Vec3::UnitX()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((rotationFromKukaAbc({0, 0, degToRad(90)}) * Vec3::UnitY() - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((rotationFromFanucWpr({degToRad(90), 0, 0}) * Vec3::UnitY() - Vec3::UnitZ()).norm(), 0.0,
              1e-15);
  EXPECT_NEAR((rotationFromFanucWpr({0, 0, degToRad(90)}) * Vec3::UnitX() - Vec3::UnitY()).norm(), 0.0,
              1e-15);
  // Intrinsic Z-Y'-X'' = the product Rz Ry Rx; FANUC fixed X then Y then Z = the same product.
  const Mat3 expected = about(Vec3::UnitZ(), 30) * about(Vec3::UnitY(), -20) * about(Vec3::UnitX(), 110);
  EXPECT_NEAR((rotationFromKukaAbc({degToRad(30), degToRad(-20), degToRad(110)}) - expected).norm(), 0.0,
              1e-14);
  EXPECT_NEAR((rotationFromFanucWpr({degToRad(110), degToRad(-20), degToRad(30)}) - expected).norm(), 0.0,
              1e-14);
}

TEST(EulerAngles, KukaAbcEqualsFanucRpwForOneMatrix)
{
  const Mat3 r = about(Vec3(1, 2, 3).normalized(), 77.0);
  const KukaAbc k = kukaAbcFromRotation(r);
  const FanucWpr f = fanucWprFromRotation(r);
  EXPECT_DOUBLE_EQ(k.a, f.r);
  EXPECT_DOUBLE_EQ(k.b, f.p);
  EXPECT_DOUBLE_EQ(k.c, f.w);
}

TEST(EulerAngles, RandomRotationsRoundTripInRange)
{
  std::mt19937 rng(5);
  std::normal_distribution<double> g;
  for (int i = 0; i < 2000; ++i) {
    const Mat3 r = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized().toRotationMatrix();
    const KukaAbc k = kukaAbcFromRotation(r);
    EXPECT_LE(std::abs(k.b), kPi / 2 + 1e-15);
    EXPECT_LE(std::abs(k.a), kPi);
    EXPECT_LE(std::abs(k.c), kPi);
    EXPECT_LT(rotationAngleBetween(rotationFromKukaAbc(k), r), 1e-12);
    EXPECT_LT(rotationAngleBetween(rotationFromFanucWpr(fanucWprFromRotation(r)), r), 1e-12);
  }
}

TEST(EulerAngles, GimbalLockRoundTripsThroughBothConventions)
{
  for (double y : {90.0, -90.0}) {
    for (double z : {-170.0, -45.0, 0.0, 30.0, 180.0}) {
      for (double x : {-120.0, 0.0, 60.0}) {
        SCOPED_TRACE(testing::Message() << "z " << z << " y " << y << " x " << x);
        const Mat3 r = about(Vec3::UnitZ(), z) * about(Vec3::UnitY(), y) * about(Vec3::UnitX(), x);
        const KukaAbc k = kukaAbcFromRotation(r);
        EXPECT_NEAR(radToDeg(k.b), y, 1e-9);
        EXPECT_TRUE(std::isfinite(k.a) && std::isfinite(k.c));
        EXPECT_LT(rotationAngleBetween(rotationFromKukaAbc(k), r), 1e-12);
        const FanucWpr f = fanucWprFromRotation(r);
        EXPECT_NEAR(radToDeg(f.p), y, 1e-9);
        EXPECT_LT(rotationAngleBetween(rotationFromFanucWpr(f), r), 1e-12);
      }
    }
  }
}

TEST(EulerAngles, NearGimbalLockStaysAccurate)
{
  for (double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
    const Mat3 r =
        about(Vec3::UnitZ(), 40.0) * about(Vec3::UnitY(), 90.0 - eps) * about(Vec3::UnitX(), -25.0);
    EXPECT_LT(rotationAngleBetween(rotationFromKukaAbc(kukaAbcFromRotation(r)), r), 1e-10) << eps;
  }
}

TEST(EulerAngles, RotationAngleBetweenMeasuresSmallAngles)
{
  const Mat3 a = about(Vec3(0.3, -1, 2).normalized(), 50.0);
  EXPECT_NEAR(rotationAngleBetween(a, a * about(Vec3::UnitX(), 1e-6)), degToRad(1e-6), 1e-15);
  EXPECT_NEAR(rotationAngleBetween(a, a * about(Vec3::UnitY(), 170.0)), degToRad(170.0), 1e-12);
}

}  // namespace
}  // namespace spira
