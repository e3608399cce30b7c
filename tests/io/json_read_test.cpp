#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "spira/base/error.h"
#include "spira/io/json_read.h"

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

std::string cborRefusal(const std::string& bytes)
{
  try {
    json_read::parseCbor(bytes, "p.cbor", "fix it");
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(JsonRead, CborReadsWhatTheLibraryWrites)
{
  const nlohmann::json value = {{"a", {1, 2.5, "x", nullptr}}, {"b", {{"c", true}}}};
  const std::vector<std::uint8_t> cbor = nlohmann::json::to_cbor(value);
  EXPECT_EQ(json_read::parseCbor(std::string(cbor.begin(), cbor.end()), "p.cbor", "fix it"), value);
}

// Nesting is bounded before the recursive decoder can overflow the stack (found by fuzzing).
TEST(JsonRead, CborNestedDeeperThan64LevelsIsRefused)
{
  EXPECT_EQ(cborRefusal(std::string(64, '\x81') + '\x01'), "accepted");
  EXPECT_EQ(cborRefusal(std::string(65, '\x81') + '\x01'), "p.cbor: the content nests deeper than 64 levels");
  EXPECT_EQ(cborRefusal(std::string(100000, '\x81')), "p.cbor: the content nests deeper than 64 levels");
}

TEST(JsonRead, MalformedCborIsPlacedOrNamedWithoutLibraryText)
{
  EXPECT_EQ(cborRefusal("\x82\x01"), "p.cbor: the binary content is malformed at byte 3");
  EXPECT_EQ(cborRefusal(std::string("\xbb\x40\x59\x00\x00\x00\x00\x00\x00", 9)),
            "p.cbor: the binary content declares a size it cannot hold");
  EXPECT_EQ(cborRefusal("\xc1\x01"), "p.cbor: the binary content is malformed at byte 1");  // a tag
}

}  // namespace
}  // namespace spira::test
