#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/plugin/param_cli.h"
#include "spira/plugin/parameter.h"

namespace spira {
namespace {

ParamSchema sampleSchema()
{
  return ParamSchema({
      {"layer_height",
       ParamType::Double,
       2.0,
       0.1,
       10.0,
       "mm",
       "Layer height",
       "Nominal deposit height.",
       "Window",
       {}},
      {"points_per_rev",
       ParamType::Int,
       std::int64_t{360},
       8.0,
       100000.0,
       "",
       "Points per revolution",
       "Generatrix count.",
       "Discretisation",
       {}},
      {"angle", ParamType::Double, 90.0, -180.0, 180.0, "deg", "Angle", "An angle.", "Geometry", {}},
      {"wfs", ParamType::Double, 2.4, 0.0, 30.0, "m/min", "Wire feed", "Wire-feed speed.", "Process", {}},
      {"layer_mode",
       ParamType::Choice,
       std::string("floor"),
       {},
       {},
       "",
       "Layer mode",
       "How layers are counted.",
       "Window",
       {"floor", "centered"}},
      {"smooth", ParamType::Bool, true, {}, {}, "", "Smooth", "Smooth the path.", "Path", {}},
  });
}

TEST(ParamSchema, DefaultsAreCompleteAndValid)
{
  const auto schema = sampleSchema();
  EXPECT_TRUE(schema.selfCheck().empty());
  const ParamSet d = schema.defaults();
  EXPECT_EQ(d.values().size(), 6u);
  EXPECT_DOUBLE_EQ(d.getDouble("layer_height"), 2.0);
  EXPECT_EQ(d.getInt("points_per_rev"), 360);
  EXPECT_EQ(d.getString("layer_mode"), "floor");
  EXPECT_TRUE(d.getBool("smooth"));
}

TEST(ParamSchema, InternalUnitsConvertOnce)
{
  const auto schema = sampleSchema();
  const ParamSet d = schema.defaults();
  EXPECT_NEAR(d.internal(schema, "angle"), 1.5707963267948966, 1e-15);
  EXPECT_NEAR(d.internal(schema, "wfs"), 40.0, 1e-12);  // 2.4 m/min = 40 mm/s
  EXPECT_DOUBLE_EQ(d.internal(schema, "layer_height"), 2.0);
}

TEST(ParamSchema, ValidationNamesKeyAndRange)
{
  const auto schema = sampleSchema();
  ParamSet s;
  s.set("layer_height", 11.0);
  try {
    schema.validate(s);
    FAIL() << "out-of-range value accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("layer_height"), std::string::npos);
    EXPECT_NE(e.hint().find("between 0.1 and 10 mm"), std::string::npos);
  }
  ParamSet c;
  c.set("layer_mode", std::string("middle"));
  EXPECT_THROW(schema.validate(c), InputError);
  ParamSet u;
  u.set("nonexistent", 1.0);
  EXPECT_THROW(schema.validate(u), InputError);
}

TEST(ParamSchema, SelfCheckFindsBrokenDeclarations)
{
  const ParamSchema bad({
      {"BadKey", ParamType::Double, 1.0, {}, {}, "", "L", "T", "C", {}},
      {"dup", ParamType::Double, 1.0, 2.0, 3.0, "", "L", "T", "C", {}},
      {"dup", ParamType::Int, 1.0, {}, {}, "", "", "", "", {}},
      {"choice", ParamType::Choice, std::string("x"), {}, {}, "", "L", "T", "C", {}},
  });
  const auto problems = bad.selfCheck();
  auto mentions = [&](const std::string& s) {
    for (const auto& p : problems)
      if (p.find(s) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(mentions("'BadKey' is not snake_case"));
  EXPECT_TRUE(mentions("'dup' declared twice"));
  EXPECT_TRUE(mentions("'dup' default is invalid"));
  EXPECT_TRUE(mentions("'dup' has no label"));
  EXPECT_TRUE(mentions("'dup' default does not match its type"));
  EXPECT_TRUE(mentions("'choice' has no choices"));
}

TEST(ParamSet, JsonRoundTripKeepsTypes)
{
  const auto schema = sampleSchema();
  ParamSet s = schema.defaults();
  s.set("layer_height", 0.1);
  const ParamSet back = ParamSet::fromJson(nlohmann::json::parse(s.toJson().dump()), &schema);
  EXPECT_EQ(back, s);
  // A double parameter written as a whole number in JSON still reads back as a double.
  const ParamSet w = ParamSet::fromJson(nlohmann::json::parse(R"({"layer_height": 3})"), &schema);
  EXPECT_TRUE(std::holds_alternative<double>(w.values().at("layer_height")));
}

TEST(ParamCli, FlagsComeFromSchema)
{
  const auto schema = sampleSchema();
  ParamSet values;
  const std::vector<std::string> args = {
      "part.stl",    "--layer-height",   "1.5", "--layer-mode=centered", "--no-smooth", "--json",
      "--angle=-30", "--points-per-rev", "720"};
  const auto rest = consumeParamFlags(args, {FlagTarget{"test", &schema, &values}});
  EXPECT_EQ(rest, (std::vector<std::string>{"part.stl", "--json"}));
  EXPECT_DOUBLE_EQ(values.getDouble("layer_height"), 1.5);
  EXPECT_EQ(values.getString("layer_mode"), "centered");
  EXPECT_FALSE(values.getBool("smooth"));
  EXPECT_DOUBLE_EQ(values.getDouble("angle"), -30.0);
  EXPECT_EQ(values.getInt("points_per_rev"), 720);
}

TEST(ParamCli, BadFlagValuesAreInputErrors)
{
  const auto schema = sampleSchema();
  ParamSet values;
  EXPECT_THROW(consumeParamFlags({"--layer-height", "abc"}, {FlagTarget{"t", &schema, &values}}), InputError);
  EXPECT_THROW(consumeParamFlags({"--layer-height", "50"}, {FlagTarget{"t", &schema, &values}}), InputError);
  EXPECT_THROW(consumeParamFlags({"--points-per-rev", "1.5"}, {FlagTarget{"t", &schema, &values}}),
               InputError);
  EXPECT_THROW(consumeParamFlags({"--layer-height"}, {FlagTarget{"t", &schema, &values}}), InputError);
}

TEST(ParamCli, HelpShowsUnitsDefaultsAndRanges)
{
  const auto schema = sampleSchema();
  ParamSet values;
  const std::string help = paramFlagsHelp({FlagTarget{"decomposer.test", &schema, &values}});
  EXPECT_NE(help.find("--layer-height X[mm]"), std::string::npos);
  EXPECT_NE(help.find("Default: 2 mm; range 0.1 .. 10"), std::string::npos);
  EXPECT_NE(help.find("--layer-mode floor|centered"), std::string::npos);
  EXPECT_NE(help.find("[Process]"), std::string::npos);
}

}  // namespace
}  // namespace spira
