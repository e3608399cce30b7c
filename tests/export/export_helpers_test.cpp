// Program names, splitting, text and the all-or-nothing file set.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "export_test_data.h"
#include "spira/base/error.h"
#include "spira/export/fixed_number.h"
#include "spira/export/program_header.h"
#include "spira/export/program_names.h"
#include "spira/export/program_split.h"
#include "support/test_support.h"

namespace spira {
namespace {

bool validIdentifier(const std::string& s, size_t maxLength, bool upperOnly)
{
  if (s.empty() || s.size() > maxLength || !std::isalpha(static_cast<unsigned char>(s[0]))) return false;
  for (char c : s) {
    const bool ok = std::isdigit(static_cast<unsigned char>(c)) || c == '_' || (c >= 'A' && c <= 'Z') ||
                    (!upperOnly && c >= 'a' && c <= 'z');
    if (!ok) return false;
  }
  return true;
}

TEST(ProgramNames, KrlKeepsCaseAndReplacesOtherCharacters)
{
  EXPECT_EQ(sanitizeProgramName("my part-v2.stl", krlNameRules()), "my_part_v2_stl");
  EXPECT_EQ(sanitizeProgramName("  --dome--  ", krlNameRules()), "dome");
  EXPECT_EQ(sanitizeProgramName("3d print", krlNameRules()), "P3d_print");
  EXPECT_EQ(sanitizeProgramName("\xC3\x9Cn\xC3\xAF"
                                "code na\xC3\xAFve",
                                krlNameRules()),
            "n_code_na_ve");
  EXPECT_EQ(sanitizeProgramName("", krlNameRules()), "SPIRA");
  EXPECT_EQ(sanitizeProgramName("#%&", krlNameRules()), "SPIRA");
}

TEST(ProgramNames, KrlCutsAt24AndAvoidsKeywords)
{
  const std::string cut = sanitizeProgramName("a_very_long_program_name_for_the_dome", krlNameRules());
  EXPECT_EQ(cut, "a_very_long_program_name");
  EXPECT_EQ(cut.size(), 24u);
  EXPECT_EQ(sanitizeProgramName("end", krlNameRules()), "end_PRG");
  EXPECT_EQ(sanitizeProgramName("Lin", krlNameRules()), "Lin_PRG");
  // Cut leaves a trailing underscore: it is trimmed.
  EXPECT_EQ(sanitizeProgramName("abcdefghijklmnopqrstuvw_xyz", krlNameRules()), "abcdefghijklmnopqrstuvw");
}

TEST(ProgramNames, FanucIsUppercaseAndAtMost36)
{
  EXPECT_EQ(sanitizeProgramName("dome r20 (v3)", fanucNameRules()), "DOME_R20_V3");
  const std::string longName(50, 'q');
  EXPECT_EQ(sanitizeProgramName(longName, fanucNameRules()), std::string(36, 'Q'));
  EXPECT_EQ(sanitizeProgramName("call", fanucNameRules()), "CALL_PRG");
}

TEST(ProgramNames, SplitPartsAreValidDistinctAndNumberedInOrder)
{
  const ProgramNames k = splitProgramNames("a_very_long_program_name_for_the_dome", 3, krlNameRules());
  EXPECT_EQ(k.main, "a_very_long_program_name");
  ASSERT_EQ(k.parts.size(), 3u);
  EXPECT_EQ(k.parts[0], "a_very_long_program_001");
  EXPECT_EQ(k.parts[2], "a_very_long_program_003");
  for (const auto& p : k.parts) EXPECT_TRUE(validIdentifier(p, 24, false)) << p;
  const ProgramNames f = splitProgramNames("dome", 1500, fanucNameRules());
  EXPECT_EQ(f.parts.front(), "DOME_0001");
  EXPECT_EQ(f.parts.back(), "DOME_1500");
  EXPECT_TRUE(splitProgramNames("x", 0, fanucNameRules()).parts.empty());
}

TEST(ProgramSplit, EvenConsecutiveRangesUnderTheLimit)
{
  const auto r = splitEvenly(10, 3);
  ASSERT_EQ(r.size(), 4u);
  EXPECT_EQ(r[0], (IndexRange{0, 3}));
  EXPECT_EQ(r[1], (IndexRange{3, 6}));
  EXPECT_EQ(r[2], (IndexRange{6, 8}));
  EXPECT_EQ(r[3], (IndexRange{8, 10}));
  EXPECT_EQ(splitEvenly(10, 10).size(), 1u);
  EXPECT_TRUE(splitEvenly(0, 5).empty());
  EXPECT_EQ(splitEvenly(7, 0).size(), 7u);
  const auto big = splitEvenly(100001, 15000);
  ASSERT_EQ(big.size(), 7u);
  size_t covered = 0;
  for (const auto& x : big) {
    EXPECT_LE(x.size(), 15000u);
    EXPECT_GE(x.size(), 14285u);
    EXPECT_EQ(x.begin, covered);
    covered = x.end;
  }
  EXPECT_EQ(covered, 100001u);
}

TEST(ProgramText, PlainTextAndWrapping)
{
  EXPECT_EQ(plainText("na\xC3\xAFve;x\ty", ";"), "na?ve x y");
  const auto lines = wrapText("Spira 0.1.0 WAAM deposition program", 12);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "Spira 0.1.0");
  EXPECT_EQ(lines[1], "WAAM");
  EXPECT_EQ(lines[2], "deposition");
  EXPECT_EQ(lines[3], "program");
  const auto cut = wrapText("abcdefghij", 4);
  ASSERT_EQ(cut.size(), 3u);
  EXPECT_EQ(cut[2], "ij");
  EXPECT_EQ(wrapText("", 10).size(), 1u);
}

TEST(ProgramText, FixedNumbers)
{
  std::string s;
  appendFixed(s, -0.0004, 3);
  EXPECT_EQ(s, "0.000");
  s.clear();
  appendFixed(s, 1.23456, 3, 9);
  EXPECT_EQ(s, "    1.235");
  s.clear();
  appendFixed(s, -179.99996, 4);
  EXPECT_EQ(s, "-180.0000");
  EXPECT_DOUBLE_EQ(roundedTo(0.0061234, 5), 0.00612);
}

TEST(ProgramHeader, OrderAndPlainText)
{
  const auto lines = programHeaderLines(
      {{"date", "2024-05-01"}, {"part", "d\xC3\xB4me.stl"}, {"h", "2 mm"}, {"cell", "kr16"}},
      {{"tool", "1"}});
  ASSERT_EQ(lines.size(), 6u);
  EXPECT_EQ(lines[0].rfind("Spira ", 0), 0u);
  EXPECT_EQ(lines[1], "part: d?me.stl");
  EXPECT_EQ(lines[2], "cell: kr16");
  EXPECT_EQ(lines[3], "date: 2024-05-01");
  EXPECT_EQ(lines[4], "h: 2 mm");
  EXPECT_EQ(lines[5], "tool: 1");
}

}  // namespace
}  // namespace spira
