// The thermal stage's result in the document: frames quantised within half a step, the project
// file's round trip bit for bit, results without it (older files) and damaged ones.
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "document/document_test_data.h"
#include "spira/base/error.h"
#include "spira/document/plan_report.h"
#include "spira/document/project_file.h"
#include "spira/document/results.h"

namespace spira {
namespace {

TEST(ThermalResult, FramesKeepTemperaturesWithinHalfAStepAndUnbornNodesAsNaN)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> early{20.0f, 1612.25f, nan, nan}, late{480.5f, nan, 1000.0f, 20.0f};
  const ThermalFrameSet f = ThermalFrameSet::quantise({2.0, 5.0}, {early, late});
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(f.values[0].size(), 2u);  // the unborn tail is not stored
  EXPECT_EQ(f.values[1].size(), 4u);
  EXPECT_LE(f.step, (1612.25 - 20.0) / 65000.0);
  for (size_t n = 0; n < 4; ++n) {
    if (!std::isnan(early[n])) {
      EXPECT_NEAR(f.at(0, n), early[n], 0.5 * f.step + 1e-4) << n;
    }
    EXPECT_EQ(std::isnan(f.at(0, n)), std::isnan(early[n])) << n;
    EXPECT_EQ(std::isnan(f.at(1, n)), std::isnan(late[n])) << n;
  }
  EXPECT_NEAR(f.at(1, 2), 1000.0f, 0.5 * f.step + 1e-4);
  EXPECT_EQ(f.frameAt(1.0), 0u);
  EXPECT_EQ(f.frameAt(4.9), 0u);
  EXPECT_EQ(f.frameAt(5.0), 1u);
  EXPECT_EQ(f.frameAt(99.0), 1u);
}

TEST(ThermalResult, HistoryAtANodeStartsAtItsBirth)
{
  const ThermalStageResult t = test::sampleThermal(6);
  const size_t last = t.nodes.size() - 1;  // born after the first frame
  const auto history = t.historyAt(last);
  ASSERT_EQ(history.size(), 1u);
  EXPECT_EQ(history[0][0], 2.0);
  EXPECT_NEAR(history[0][1], 1500.0 - static_cast<double>(last), t.frames.step);
  EXPECT_EQ(t.historyAt(0).size(), 2u);
}

TEST(ThermalResult, RoundTripsThroughTheProjectFileBitForBit)
{
  const DocumentState s = test::fullState();
  ASSERT_TRUE(s.results.thermal && s.results.reports.thermal);
  const DocumentState back = decodeProject(encodeProject(s));
  ASSERT_TRUE(back.results.thermal && back.results.reports.thermal);
  EXPECT_EQ(*back.results.thermal, *s.results.thermal);
  EXPECT_TRUE(std::isnan(back.results.thermal->interpass[0]));
  EXPECT_EQ(back.results.reports.thermal->limitMet, std::optional<bool>(false));
  EXPECT_EQ(back.results.reports.thermal->maxInterpass, 520.0);
  ASSERT_TRUE(back.results.thermal->replanned);
  EXPECT_EQ(*back.results.thermal->replanned, *s.results.thermal->replanned);
  // A changed value is seen as a change.
  ThermalStageResult other = *s.results.thermal;
  other.risk[1] = 1;
  EXPECT_NE(other, *s.results.thermal);
}

TEST(ThermalResult, ResultsWithoutItReadAsNotSimulated)
{
  Results r = test::fullState().results;
  nlohmann::json j = resultsToJson(r);
  j.erase("thermal");
  j["reports"].erase("thermal");
  const Results back = resultsFromJson(j);
  EXPECT_FALSE(back.thermal || back.reports.thermal);
  EXPECT_TRUE(back.process && back.kinematics);
}

TEST(ThermalResult, ADamagedResultIsAnInputError)
{
  nlohmann::json j = resultsToJson(test::fullState().results);
  nlohmann::json bad = j;
  bad["thermal"]["points"] = 5;
  EXPECT_THROW(resultsFromJson(bad), InputError);
  bad = j;
  bad["thermal"]["triangles"] =
      nlohmann::json::binary_t(std::vector<std::uint8_t>{255, 255, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0});
  EXPECT_THROW(resultsFromJson(bad), InputError);
  bad = j;
  bad["thermal"]["frames"]["values"].erase(0);
  EXPECT_THROW(resultsFromJson(bad), InputError);
}

TEST(ThermalResult, ReportJsonListsItUnderThermal)
{
  const Results r = test::fullState().results;
  const nlohmann::json report = mergedPlanReport(r);
  ASSERT_TRUE(report.contains("thermal"));
  EXPECT_EQ(report["thermal"]["max_interpass_C"], 520.0);
  EXPECT_EQ(report["thermal"]["material"], "G3Si1");
  Results without = r;
  without.setThermal(nullptr);
  EXPECT_FALSE(mergedPlanReport(without).contains("thermal"));
}

}  // namespace
}  // namespace spira
