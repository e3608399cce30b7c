// The machine file: the bundled example as documented, and every kind of file that cannot drive a
// head refused with the axis and the field named.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "export_gcode/gcode_machine.h"
#include "spira/base/error.h"
#include "support/test_support.h"

namespace spira {
namespace {

nlohmann::json bundled()
{
  return nlohmann::json::parse(
      test::readBytes(test::sourceDir() / "resources" / "machines" / "gantry_ca_head.machine"));
}

TEST(GcodeMachine, TheBundledHeadIsCAboutZCarryingAAboutX)
{
  const GcodeMachine m = machineFromText(bundled().dump(), "bundled");
  EXPECT_EQ(m.linear[0].letter, "X");
  EXPECT_EQ(m.linear[2].letter, "Z");
  EXPECT_EQ(m.rotary[0].letter, "C");
  EXPECT_EQ(m.rotary[1].letter, "A");
  EXPECT_EQ(m.rotary[0].about, Vec3::UnitZ());
  EXPECT_EQ(m.rotary[1].about, Vec3::UnitX());
  EXPECT_EQ(m.secondToTip, Vec3(0.0, 0.0, -150.0));
  EXPECT_EQ(m.toolDirection, Vec3(0.0, 0.0, -1.0));
  EXPECT_DOUBLE_EQ(m.rotary[1].minDeg, -95.0);
  EXPECT_DOUBLE_EQ(m.maxFeed, 6000.0);
  EXPECT_EQ(m.wireFeed, "M67 E0 Q{wfs}");
  EXPECT_EQ(m.arcOn, "M62 P0");
}

void expectRefused(const nlohmann::json& j, const std::vector<std::string>& needles)
{
  try {
    machineFromText(j.dump(), "machine file m.machine");
    ADD_FAILURE() << "accepted: " << j.dump();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("machine file m.machine"), std::string::npos) << what;
    for (const auto& n : needles)
      EXPECT_NE(what.find(n), std::string::npos) << "'" << n << "' not in: " << what;
    EXPECT_FALSE(e.hint().empty());
  }
}

TEST(GcodeMachine, BadFilesAreRefusedNamingTheAxisAndTheField)
{
  nlohmann::json j = bundled();
  j["linear_axes"][2]["letter"] = "Y";
  expectRefused(j, {"linear_axes[2] (Z)", "letter Y is used by two axes"});

  j = bundled();
  j["rotary_axes"][1]["letter"] = "C";
  expectRefused(j, {"rotary_axes[1]", "letter C is used by two axes"});

  j = bundled();
  j["rotary_axes"][1]["letter"] = "D";
  expectRefused(j, {"rotary_axes[1]", "\"D\" is not a rotary axis"});

  j = bundled();
  j["rotary_axes"][0]["about"] = {0, 0, 0};
  expectRefused(j, {"rotary_axes[0] (C)", "'about' is a zero vector"});

  j = bundled();
  j["rotary_axes"][1]["about"] = {0, 0, -2};
  expectRefused(j, {"rotary_axes", "C and A turn about parallel axes"});

  j = bundled();
  j["rotary_axes"][1]["min_deg"] = 95;
  expectRefused(j, {"rotary_axes[1] (A)", "min_deg 95 is not below max_deg 95"});

  j = bundled();
  j["linear_axes"][0]["max_mm"] = -5;
  expectRefused(j, {"linear_axes[0] (X)", "min_mm 0 is not below max_mm -5"});

  j = bundled();
  j["linear_axes"][1].erase("max_mm");
  expectRefused(j, {"linear_axes[1] (Y)", "'max_mm' is missing"});

  j = bundled();
  j["tool_direction"] = {0, 0, 1};  // along A's partner C: the tilt is then the only freedom
  j["rotary_axes"][1]["about"] = "Z";
  j["rotary_axes"][0]["about"] = "X";
  expectRefused(j, {"tool_direction", "second rotary axis A"});

  j = bundled();
  j["process"]["wire_feed"] = "S100";
  expectRefused(j, {"process", "'wire_feed' \"S100\" has no {wfs}"});

  j = bundled();
  j["spira_machine"] = 2;
  expectRefused(j, {"spira_machine"});
}

}  // namespace
}  // namespace spira
