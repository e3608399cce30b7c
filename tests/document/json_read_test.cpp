#include <gtest/gtest.h>

#include <string>

#include "spira/base/error.h"
#include "spira/document/json_read.h"

namespace spira::test {
namespace {

std::string refusal(const std::string& text)
{
  try {
    json_read::parse(text, "f.json", "fix it");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

// A text that stops early is placed where it stops, the place the user has to look at.
TEST(JsonRead, TextThatEndsEarlyIsPlacedAtItsEnd)
{
  EXPECT_EQ(refusal("{\"a\": ["), "f.json, line 1, column 8: the JSON text ends too early");
  EXPECT_EQ(refusal("{\n  \"a\": 1,\n"), "f.json, line 3, column 1: the JSON text ends too early");
  EXPECT_EQ(refusal(""), "f.json, line 1, column 1: the JSON text ends too early");
}

TEST(JsonRead, WrongTokenAndHugeNumberAreNamedWithTheirPlace)
{
  EXPECT_EQ(refusal("{\"a\": 1 2}"), "f.json, line 1, column 9: unexpected '2' (not valid JSON)");
  EXPECT_EQ(refusal("[1e999]"), "f.json, line 1, column 2: the number 1e999 is beyond the range of a double");
}

}  // namespace
}  // namespace spira::test
