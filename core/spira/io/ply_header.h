#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace spira {

enum class PlyEncoding { Ascii, BinaryLittleEndian, BinaryBigEndian };

// The PLY scalar types under both their classic and their sized names (char = int8, float32 = float).
enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

size_t plyTypeSize(PlyType type);
bool plyTypeIsInteger(PlyType type);

// A scalar property, or a list property (`isList`) whose item count has type `countType`.
struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // the value type, or the list items' type
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  size_t line = 0;  // the header line that declares it
  std::vector<PlyProperty> properties;

  // The index of the property called `name`, or -1.
  int find(std::string_view propertyName) const;
  // Bytes one binary item takes at least: scalars plus list counts (a list may be empty).
  std::uint64_t minBinaryBytes() const;
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  size_t bodyOffset = 0;  // the first byte after the end_header line
  size_t lines = 0;       // the header's line count; the body's first ASCII line is lines + 1
};

// Headers longer than this without end_header are refused: no exporter writes one, and a missing
// end_header must not make the reader scan a whole large file for it.
constexpr size_t kMaxPlyHeaderBytes = 64 * 1024;

// At most 40 characters of file text for a message, control and non-ASCII bytes shown as '?'.
std::string plyExcerpt(std::string_view text);

// Parses and validates the header: the "ply" magic, one format line (version 1.0), element and
// property lines, comment and obj_info lines, end_header. `source` names the file in messages.
// Throws InputError naming the line and what is wrong.
PlyHeader parsePlyHeader(std::string_view bytes, const std::string& source);

}  // namespace spira
