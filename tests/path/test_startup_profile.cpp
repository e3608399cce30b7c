#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "spira/base/error.h"
#include "spira/path/startup_profile.h"

using spira::InputError;
using spira::StartupProfile;
using spira::StartupTransition;

// Thesis Table 3.1 (h = 1 mm, ±10 %): Δh_j = 0.2 j h; the ramps stop at j = 5 where Δh_5 = h, so
// 4 full ramps, the transition (Fig. 3.5: 0.9 -> 1.0 mm) and one constant revolution: 6 in all.
TEST(StartupProfile, ReproducesTable31AtTenPercent)
{
  const StartupProfile p(1.0, 0.9, 1.1);
  EXPECT_EQ(p.fullRamps(), 4);
  EXPECT_EQ(p.startRevolutions(), 6);
  EXPECT_EQ(p.endRevolutions(), 6);
  // Table 3.1 rows 1-4: after j ramps the highest point is j h_max, the lowest j h_min.
  for (int j = 1; j <= 4; ++j) {
    double top = 0.0, bottom = 0.0;
    for (int r = 0; r < j; ++r) {
      top += p.startStep(r, 1.0);
      bottom += p.startStep(r, 0.0);
    }
    EXPECT_NEAR(top, j * 1.1, 1e-12) << j;
    EXPECT_NEAR(bottom, j * 0.9, 1e-12) << j;
    EXPECT_NEAR(top - bottom, 0.2 * j, 1e-12) << j;
  }
  EXPECT_NEAR(p.startStep(4, 0.0), 0.9, 1e-12);
  EXPECT_NEAR(p.startStep(4, 0.5), 0.95, 1e-12);
  EXPECT_NEAR(p.startStep(4, 1.0), 1.0, 1e-12);
  for (double u : {0.0, 0.3, 1.0}) EXPECT_NEAR(p.startStep(5, u), 1.0, 1e-12);
  EXPECT_NEAR(p.climb(), 0.9, 1e-12);
  EXPECT_NEAR(p.seamStep(), 0.1, 1e-12);
}

// Fig. 4.7 (joystick, 2 mm ±10 %): four ramps 1.8 -> 2.2, revolution 5 1.8 -> 2.0, revolution 6 at 2.0.
TEST(StartupProfile, JoystickProfileAtTwoMillimetres)
{
  const StartupProfile p(2.0, 1.8, 2.2);
  ASSERT_EQ(p.startRevolutions(), 6);
  for (int r = 0; r < 4; ++r) {
    EXPECT_NEAR(p.startStep(r, 0.0), 1.8, 1e-12);
    EXPECT_NEAR(p.startStep(r, 1.0), 2.2, 1e-12);
  }
  EXPECT_NEAR(p.startStep(4, 1.0), 2.0, 1e-12);
  EXPECT_NEAR(p.startStep(5, 0.0), 2.0, 1e-12);
  EXPECT_NEAR(p.startLength(0.0), 4 * 1.8 + 1.8 + 2.0, 1e-12);
  EXPECT_NEAR(p.startLength(1.0), 4 * 2.2 + 2.0 + 2.0, 1e-12);
}

TEST(StartupProfile, OtherWindowsFollowTheRule)
{
  // Very wide: Δ = 1.1 >= h, no full ramp.
  const StartupProfile wide(1.0, 0.5, 1.6);
  EXPECT_EQ(wide.fullRamps(), 0);
  EXPECT_EQ(wide.startRevolutions(), 2);
  EXPECT_NEAR(wide.startStep(0, 0.0), 0.5, 1e-12);
  EXPECT_NEAR(wide.startStep(0, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(wide.seamStep(), 0.5, 1e-12);
  // Δ = h / 2 exactly: 1 Δ < h, 2 Δ = h ends the ramps.
  EXPECT_EQ(StartupProfile(2.0, 1.5, 2.5).fullRamps(), 1);
  // ±5 %: Δ = 0.1 h, 9 ramps, 11 start-up revolutions (h_max - h_min carries rounding noise).
  EXPECT_EQ(StartupProfile(1.0, 0.95, 1.05).fullRamps(), 9);
  EXPECT_EQ(StartupProfile(1.0, 0.95, 1.05).startRevolutions(), 11);
  // ±20 %: Δ = 0.4 h, 2 ramps (0.8 h < h, 1.2 h > h).
  EXPECT_EQ(StartupProfile(3.0, 2.4, 3.6).fullRamps(), 2);
}

TEST(StartupProfile, NominalAtAnEdgeOfTheWindow)
{
  // h == h_min: the transition is flat at h and the seam step is h_max - h, its upper bound.
  const StartupProfile low(1.0, 1.0, 1.2);
  EXPECT_EQ(low.fullRamps(), 4);
  EXPECT_EQ(low.startRevolutions(), 6);
  EXPECT_NEAR(low.startStep(4, 0.0), 1.0, 1e-12);
  EXPECT_NEAR(low.startStep(4, 1.0), 1.0, 1e-12);
  EXPECT_NEAR(low.seamStep(), 0.2, 1e-12);
  // h == h_max: 5 ramps (1.0 < 1.1), then a transition that is a full ramp.
  const StartupProfile high(1.1, 0.9, 1.1);
  EXPECT_EQ(high.fullRamps(), 5);
  EXPECT_NEAR(high.startStep(5, 1.0), 1.1, 1e-12);
  EXPECT_NEAR(high.seamStep(), -0.1, 1e-12);
}

// Invariants over many windows: every step in the window, the seam step within the half-widths,
// and start + end lengths independent of the place around the part (a flat last revolution).
TEST(StartupProfile, StepsStayInTheWindowAndTheEndLevelsTheSpiral)
{
  for (double lo : {0.5, 0.8, 0.9, 0.95, 0.99}) {
    for (double hi : {1.01, 1.05, 1.1, 1.3, 2.0}) {
      for (double h : {lo, 0.5 * (lo + hi), 1.0, hi}) {
        for (auto tr : {StartupTransition::ToNominal, StartupTransition::UniformHelix}) {
          const StartupProfile p(h, lo, hi, tr, 360);
          for (double u = 0.0; u <= 1.0; u += 0.125) {
            for (int r = 0; r < p.startRevolutions(); ++r) {
              EXPECT_GE(p.startStep(r, u), lo - 1e-12);
              EXPECT_LE(p.startStep(r, u), hi + 1e-12);
            }
            for (int r = 0; r < p.endRevolutions(); ++r) {
              EXPECT_GE(p.endStep(r, u), lo - 1e-12);
              EXPECT_LE(p.endStep(r, u), hi + 1e-12);
            }
            EXPECT_NEAR(p.startLength(u) + p.endLength(u), p.startLength(0) + p.endLength(0), 1e-12);
          }
          EXPECT_LT(p.fullRamps() * (hi - lo), h);
          EXPECT_GE((p.fullRamps() + 1) * (hi - lo), h * (1 - 1e-9));
          if (tr == StartupTransition::ToNominal) {
            EXPECT_GT(p.seamStep(), -(h - lo) - 1e-12);
            EXPECT_LE(p.seamStep(), hi - h + 1e-12);
          }
        }
      }
    }
  }
}

// The thesis text's reading: the start-up climbs h (n-1)/n, so the seam step is h / n like the
// others. At ±10 % with 360 points: transition 0.9 -> 0.9 + 359/360 - 0.8 mm.
TEST(StartupProfile, UniformHelixClimbsOneLayerPerRevolution)
{
  const StartupProfile p(1.0, 0.9, 1.1, StartupTransition::UniformHelix, 360);
  EXPECT_EQ(p.startRevolutions(), 6);
  EXPECT_NEAR(p.transitionTop(), 0.9 + 359.0 / 360.0 - 0.8, 1e-12);
  EXPECT_NEAR(p.climb(), 359.0 / 360.0, 1e-12);
  EXPECT_NEAR(p.seamStep(), 1.0 / 360.0, 1e-12);
  EXPECT_NEAR(p.startLength(1.0) - p.startLength(0.0), 359.0 / 360.0, 1e-12);
  EXPECT_THROW(StartupProfile(1.0, 0.9, 1.1, StartupTransition::UniformHelix, 0), InputError);
}

TEST(StartupProfile, RejectsBadWindowsWithAHint)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(StartupProfile(1.0, 1.1, 0.9), InputError);  // h_min > h_max
  EXPECT_THROW(StartupProfile(1.0, 1.0, 1.0), InputError);  // empty window
  EXPECT_THROW(StartupProfile(1.2, 0.9, 1.1), InputError);  // h above
  EXPECT_THROW(StartupProfile(0.8, 0.9, 1.1), InputError);  // h below
  EXPECT_THROW(StartupProfile(0.5, 0.0, 1.0), InputError);  // h_min not positive
  EXPECT_THROW(StartupProfile(nan, 0.9, 1.1), InputError);
  EXPECT_THROW(StartupProfile(1.0, 1.0 - 1e-9, 1.0 + 1e-9), InputError);  // 5e8 ramps
  try {
    StartupProfile(1.0, 1.1, 0.9);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("h_min"), std::string::npos);
    EXPECT_FALSE(e.hint().empty());
  }
}
