// The stage reports' JSON form (report.json and the project file): every key written once and read
// back to the same values, integers kept integers, an infinite value written as null, a report of
// an earlier version read with its missing keys at their defaults, and a member of the wrong type
// named by its path.
#include <gtest/gtest.h>

#include <limits>

#include <nlohmann/json.hpp>

#include "document_test_data.h"
#include "spira/base/error.h"
#include "spira/document/results.h"
#include "spira/document/stage_report_codec.h"

namespace spira::test {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

SpiralStageReport everySpiralKey()
{
  SpiralStageReport s;
  s.partType = "multi_branch";
  s.strategy = "geodesic";
  s.field = "geodesic_distance";
  s.generatrices = 120;
  s.points = 16201;
  s.revolutions = 37;
  s.hMax = 2.2;
  s.depositCheck.counts = {{"thin", 2}, {"jump", 1}};
  s.depositCheck.flaggedPoints = {{5, "unsupported", kInf, Vec3(1.0, 2.0, 3.0)}};
  s.depositCheck.coverage = CoverageRecord{100.0, 2.5, 0.025, 2.6, 1.5, Vec3(0.0, 0.5, 9.0)};
  s.solid = SolidRecord{};
  s.solid->warnings = {"thin wall"};
  s.violationPoints = {{3, 0, 7, 2.4, "start_up", true}};
  s.closurePoint = Vec3(0.0, 0.0, 60.0);
  s.closureDistance = 88.5;
  s.dwells = 3;
  s.dwellTime = 42.5;
  s.timings = {{"field", 0.5}, {"total", 1.25}};
  s.paths = {PathRecord{}};
  s.paths[0].closurePoint = Vec3(1.0, 1.0, 1.0);
  s.branching = BranchingRecord{{SaddleRecord{}}, 0.9, 12.0, true};
  return s;
}

MotionStageReport everyMotionKey()
{
  MotionStageReport m;
  m.cell = "FANUC";
  m.unreachableIndices = {4, 5};
  m.minLimitMarginPoint = 9;
  m.jointSpeed.perAxis["E2"] = {kInf, 12};
  m.jointSpeed.slowdown = SlowdownRecord{};
  m.jointSpeed.slowdown->points = {{7, kInf, 2.0, kInf, false}};
  m.jointSpeed.slowdown->maxHeight = 3.5;
  m.positionerRange = std::map<std::string, std::array<double, 2>>{{"E1", {-10.0, 45.0}}};
  m.robotCollisionLinks = {"link_4"};
  m.timings = {{"joint_motion", 0.75}};
  return m;
}

template <class Report>
Report roundTrip(const Report& r)
{
  return reportFromJson<Report>(nlohmann::json::parse(reportToJson(r).dump()), "test report", "hint");
}

TEST(StageReportCodec, SpiralReportReadsBackToTheSameValuesAndText)
{
  const SpiralStageReport s = everySpiralKey();
  const nlohmann::json j = reportToJson(s);
  const SpiralStageReport back = roundTrip(s);
  EXPECT_TRUE(sameReport(s, back));
  EXPECT_EQ(reportToJson(back).dump(), j.dump());
  EXPECT_EQ(back.points, 16201);
  EXPECT_EQ(back.closurePoint, s.closurePoint);
  EXPECT_EQ(back.depositCheck.counts.at("thin"), 2);
  EXPECT_TRUE(std::isnan(back.depositCheck.flaggedPoints[0].height));  // null: nothing below it
  EXPECT_EQ(back.branching->saddles.size(), 1u);
  // The keys report.json has always had, with their JSON types.
  EXPECT_TRUE(j.at("n_points").is_number_integer());
  EXPECT_TRUE(j.at("height_max").is_number_float());
  EXPECT_TRUE(j.at("deposit_check").at("flagged_points")[0].at("height").is_number_float());
  EXPECT_EQ(nlohmann::json::parse(j.dump()).at("deposit_check").at("flagged_points")[0].at("height"),
            nullptr);
  EXPECT_EQ(j.at("closure_point"), nlohmann::json::array({0.0, 0.0, 60.0}));
  EXPECT_EQ(j.at("closure_distance"), 88.5);
  EXPECT_EQ(j.at("paths")[0].at("role"), "");
  EXPECT_EQ(j.at("branching").at("depth_limited"), true);
  EXPECT_EQ(j.at("n_dwells"), 3);
  EXPECT_TRUE(j.at("n_dwells").is_number_integer());
  EXPECT_EQ(j.at("dwell_time_s"), 42.5);
  EXPECT_EQ(back.dwellTime, 42.5);
  EXPECT_EQ(j.size(), 45u);
}

TEST(StageReportCodec, EmptyOptionalsAreLeftOutOrWrittenAsNull)
{
  const nlohmann::json j = reportToJson(SpiralStageReport{});
  EXPECT_TRUE(j.at("closure_point").is_null());  // report.json's contract: always there
  EXPECT_FALSE(j.contains("closure_distance"));
  EXPECT_FALSE(j.contains("solid"));
  EXPECT_FALSE(j.contains("branching"));
  EXPECT_FALSE(j.contains("n_dwells"));  // a plan without a dwell keeps the report it always had
  EXPECT_FALSE(j.contains("dwell_time_s"));
  EXPECT_FALSE(j.at("deposit_check").contains("coverage"));
  EXPECT_EQ(j.size(), 40u);
  const SpiralStageReport back = roundTrip(SpiralStageReport{});
  EXPECT_FALSE(back.closurePoint);
  EXPECT_FALSE(back.solid);
}

TEST(StageReportCodec, MotionReportKeepsNullIndicesAndInfiniteSpeeds)
{
  const MotionStageReport m = everyMotionKey();
  const nlohmann::json j = nlohmann::json::parse(reportToJson(m).dump());
  EXPECT_TRUE(j.at("min_dexterity_point").is_null());
  EXPECT_EQ(j.at("min_joint_limit_margin_point"), 9);
  EXPECT_TRUE(j.at("joint_speed").at("per_axis").at("E2").at("max_percent").is_null());
  EXPECT_EQ(j.at("joint_speed").at("slowdown").at("points")[0],
            nlohmann::json::parse("[7, null, 2.0, null, false]"));
  EXPECT_EQ(j.at("positioner_range_deg").at("E1"), nlohmann::json::array({-10.0, 45.0}));
  const MotionStageReport back = roundTrip(m);
  EXPECT_TRUE(sameReport(m, back));
  EXPECT_FALSE(back.minDexterityPoint);
  EXPECT_EQ(*back.minLimitMarginPoint, 9);
  EXPECT_TRUE(std::isnan(back.jointSpeed.perAxis.at("E2").maxPercent));
  EXPECT_EQ(back.jointSpeed.slowdown->points[0].point, 7);
}

TEST(StageReportCodec, MissingKeysKeepTheirDefaults)
{
  const auto r =
      reportFromJson<SpiralStageReport>(nlohmann::json{{"n_points", 12}, {"unknown", true}}, "r", "h");
  EXPECT_EQ(r.points, 12);
  EXPECT_EQ(r.pathCount, 1);
  EXPECT_EQ(r.hMax, 0.0);
  EXPECT_TRUE(r.depositCheck.flaggedPoints.empty());
  // A whole number written as a floating-point number by another tool still reads.
  EXPECT_EQ(reportFromJson<SpiralStageReport>(nlohmann::json{{"n_points", 12.0}}, "r", "h").points, 12);
}

std::string messageOf(const nlohmann::json& j)
{
  try {
    reportFromJson<SpiralStageReport>(j, "report.json", "plan the part again");
  } catch (const InputError& e) {
    EXPECT_EQ(e.hint(), "plan the part again");
    return e.what();
  }
  return "accepted";
}

TEST(StageReportCodec, WrongTypeIsNamedByItsPath)
{
  EXPECT_EQ(messageOf({{"n_points", "many"}}),
            "report.json: field 'n_points' must be a whole number, found the string \"many\"");
  EXPECT_EQ(messageOf({{"n_points", 1.5}}),
            "report.json: field 'n_points' must be a whole number, found the number 1.5");
  EXPECT_EQ(messageOf({{"deposit_check", {{"flagged_points", {{{"kind", 3}}}}}}}),
            "report.json: field 'deposit_check.flagged_points[0].kind' must be a string, found the number 3");
  EXPECT_EQ(messageOf({{"closure_point", {1.0, 2.0}}}),
            "report.json: field 'closure_point' must be an array of 3 numbers, found a list");
  EXPECT_EQ(messageOf(nlohmann::json::array()), "report.json: expected a JSON object, found a list");
}

// The project file stores every stage report and reads it back unchanged.
TEST(StageReportCodec, ResultsRoundTripKeepsEveryReport)
{
  const Results r = fullState().results;
  const Results back = resultsFromJson(nlohmann::json::from_cbor(nlohmann::json::to_cbor(resultsToJson(r))));
  EXPECT_EQ(back.differingStages(r), 0u);
  ASSERT_TRUE(back.reports.kinematics);
  EXPECT_EQ(back.reports.kinematics->seconds, 0.5);
  EXPECT_EQ(back.reports.spiral->strategy, "geodesic");
  ASSERT_TRUE(back.exported);
  EXPECT_EQ(back.exported->files, (std::vector<std::string>{"a.src", "a.dat"}));
  // A changed figure is a changed stage.
  auto spiral = std::make_shared<SpiralStageReport>(*r.reports.spiral);
  spiral->points += 1;
  Results changed = r;
  changed.reports.spiral = spiral;
  EXPECT_EQ(changed.differingStages(r), stageBit(Stage::Spiral));
}

}  // namespace
}  // namespace spira::test
