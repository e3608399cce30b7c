#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "spira/base/error.h"
#include "spira/prep/deadband.h"

using namespace spira;

// A slowly varying wire feed with measurement-like jitter: the held setpoint never differs from the
// planned value by more than the threshold, and far fewer setpoints are written than points.
TEST(Deadband, HeldErrorIsBoundedByTheThreshold)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  std::vector<double> wfs;
  for (int i = 0; i < 2000; ++i) wfs.push_back(100.0 + 15.0 * std::sin(i * 0.01) + jitter(rng));
  for (double threshold : {0.0, 0.05, 0.5, 2.0}) {
    const DeadbandResult r = applyDeadband(wfs, threshold);
    ASSERT_EQ(r.emit.size(), wfs.size());
    ASSERT_EQ(r.held.size(), wfs.size());
    EXPECT_TRUE(r.emit[0]);
    size_t emitted = 0;
    double worst = 0.0;
    for (size_t i = 0; i < wfs.size(); ++i) {
      worst = std::max(worst, std::abs(r.held[i] - wfs[i]));
      if (r.emit[i]) {
        ++emitted;
        EXPECT_EQ(r.held[i], wfs[i]);  // a written setpoint is the planned value there
      } else {
        EXPECT_EQ(r.held[i], r.held[i - 1]);  // nothing written: the previous setpoint holds
        EXPECT_LE(std::abs(wfs[i] - r.held[i]), threshold);
      }
    }
    EXPECT_EQ(emitted, r.emitted);
    EXPECT_LE(worst, threshold);
    EXPECT_DOUBLE_EQ(worst, r.maxError);
    if (threshold == 0.0) {
      EXPECT_EQ(r.emitted, wfs.size());
    }
    // The sine moves by at most 0.15 + 0.04 jitter per point: writing on every step of 2 mm/s takes at
    // least range / (threshold + 0.19) setpoints and far fewer than the point count.
    if (threshold == 2.0) {
      EXPECT_GE(r.emitted, static_cast<size_t>(30.0 / 2.19));
      EXPECT_LT(r.emitted, wfs.size() / 10);
    }
  }
}

TEST(Deadband, StepIsWrittenOnceAndSmallMovesAreNot)
{
  const DeadbandResult r = applyDeadband({5.0, 5.04, 4.97, 6.0, 6.0, 6.02, 5.9}, 0.05);
  EXPECT_EQ(r.emit, (std::vector<bool>{true, false, false, true, false, false, true}));
  EXPECT_EQ(r.held, (std::vector<double>{5.0, 5.0, 5.0, 6.0, 6.0, 6.0, 5.9}));
  EXPECT_EQ(r.emitted, 3u);
  EXPECT_THROW(applyDeadband({1.0}, -0.1), InputError);
  EXPECT_EQ(applyDeadband({}, 0.1).emitted, 0u);
}
