// A settings struct bound to its parameters: the schema comes from the entries and a ParamSet is
// read into the fields, converted from the shown unit, with choices mapped to enum values.
#include <gtest/gtest.h>

#include "spira/base/error.h"
#include "spira/plugin/settings_binding.h"

namespace spira {
namespace {

enum class Shape { Round, Square };

struct Inner {
  double speed = 0.0;  // mm/s
};

struct Toy {
  double length = 0.0;  // mm
  double angle = 0.0;   // rad
  bool on = false;
  Shape shape = Shape::Round;
  std::string file;
  Inner inner;
};

using ToyBinding = SettingsBinding<Toy>;

const ToyBinding& toyBinding()
{
  static const ToyBinding binding({
      ToyBinding::number(numberParam("length", 4.0, 1.0, 10.0, "mm", {"Length", "What it sets.", "A"}),
                         &Toy::length),
      ToyBinding::number(numberParam("angle", 90.0, 0.0, 180.0, "deg", {"Angle", "What it sets.", "A"}),
                         &Toy::angle),
      ToyBinding::flag(flagParam("on", true, {"On", "What it sets.", "A"}), &Toy::on),
      ToyBinding::choice("shape", "square", {{"round", Shape::Round}, {"square", Shape::Square}},
                         {"Shape", "What it sets.", "B"}, &Toy::shape),
      ToyBinding::text(pathParam("file", {"File", "What it sets.", "B"}), &Toy::file),
      ToyBinding::number(numberParam("speed", 3.0, 0.0, 60.0, "m/min", {"Speed", "What it sets.", "B"}),
                         [](Toy& t) -> double& { return t.inner.speed; }),
  });
  return binding;
}

TEST(SettingsBinding, SchemaHasOneDefinitionPerEntryInOrder)
{
  const ParamSchema& schema = toyBinding().schema();
  ASSERT_EQ(schema.defs().size(), 6u);
  EXPECT_EQ(schema.defs()[0].key, "length");
  EXPECT_EQ(schema.defs()[3].key, "shape");
  EXPECT_EQ(schema.defs()[3].type, ParamType::Choice);
  EXPECT_EQ(schema.defs()[3].choices, (std::vector<std::string>{"round", "square"}));
  EXPECT_EQ(schema.defs()[3].defaultValue, ParamValue(std::string("square")));
  EXPECT_EQ(schema.defs()[4].type, ParamType::Path);
  EXPECT_EQ(schema.selfCheck(), std::vector<std::string>());
}

TEST(SettingsBinding, ReadsDefaultsConvertedToInternalUnits)
{
  Toy t;
  toyBinding().read(ParamSet(), t);
  EXPECT_DOUBLE_EQ(t.length, 4.0);
  EXPECT_DOUBLE_EQ(t.angle, 1.5707963267948966);
  EXPECT_TRUE(t.on);
  EXPECT_EQ(t.shape, Shape::Square);
  EXPECT_EQ(t.file, "");
  EXPECT_DOUBLE_EQ(t.inner.speed, 50.0);  // 3 m/min
}

TEST(SettingsBinding, ReadsGivenValuesAndRefusesOutOfRangeOnesByKey)
{
  ParamSet v;
  v.set("length", std::int64_t{7});
  v.set("shape", std::string("round"));
  v.set("on", false);
  v.set("file", std::string("a.csv"));
  Toy t;
  toyBinding().read(v, t);
  EXPECT_DOUBLE_EQ(t.length, 7.0);
  EXPECT_EQ(t.shape, Shape::Round);
  EXPECT_FALSE(t.on);
  EXPECT_EQ(t.file, "a.csv");
  v.set("length", 11.0);
  try {
    toyBinding().read(v, t);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("length"), std::string::npos) << e.what();
  }
  v.set("length", 2.0);
  v.set("shape", std::string("oval"));
  EXPECT_THROW(toyBinding().read(v, t), InputError);
}

TEST(ParamBuilders, FillTheFieldsOfTheirType)
{
  const ParamDef n = numberParam("gap", 1.5, 0.5, 3.0, "mm", {"Gap", "Tip.", "Group"});
  EXPECT_EQ(n.type, ParamType::Double);
  EXPECT_EQ(n.defaultValue, ParamValue(1.5));
  EXPECT_EQ(*n.min, 0.5);
  EXPECT_EQ(*n.max, 3.0);
  EXPECT_EQ(n.unit, "mm");
  EXPECT_EQ(n.label, "Gap");
  EXPECT_EQ(n.tooltip, "Tip.");
  EXPECT_EQ(n.category, "Group");
  const ParamDef i = integerParam("count", 3, 1, 9, {"Count", "What it sets.", "Group"});
  EXPECT_EQ(i.type, ParamType::Int);
  EXPECT_EQ(i.defaultValue, ParamValue(std::int64_t{3}));
  EXPECT_EQ(*i.max, 9.0);
  const ParamDef c = choiceParam("mode", "b", {"a", "b"}, {"Mode", "What it sets.", "Group"});
  EXPECT_EQ(c.type, ParamType::Choice);
  EXPECT_EQ(c.choices.size(), 2u);
  EXPECT_FALSE(c.min.has_value());
  EXPECT_EQ(flagParam("on", true, {"On", "What it sets.", "Group"}).defaultValue, ParamValue(true));
  const ParamDef p = pathParam("table", {"Table", "What it sets.", "Group"});
  EXPECT_EQ(p.type, ParamType::Path);
  EXPECT_EQ(p.defaultValue, ParamValue(std::string()));
  for (const ParamDef& d : {n, i, c, p})
    EXPECT_EQ(ParamSchema({d}).selfCheck(), std::vector<std::string>()) << d.key;
}

}  // namespace
}  // namespace spira
