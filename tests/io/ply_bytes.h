#pragma once

#include <cstring>
#include <string>
#include <utility>

#include "spira/base/progress.h"
#include "spira/io/ply_reader.h"

namespace spira::test {

// Builds PLY files value by value in either byte order, for layouts Spira's writer does not produce.
struct PlyBytes {
  explicit PlyBytes(bool bigEndian, std::string lineEnd = "\n") : big(bigEndian), eol(std::move(lineEnd)) {}

  // "ply", the format line of this byte order, the given element and property lines, end_header.
  void header(const std::string& lines)
  {
    bytes = "ply" + eol + "format " + (big ? "binary_big_endian" : "binary_little_endian") + " 1.0" + eol +
            lines + "end_header" + eol;
  }

  template <class T>
  void put(T value)
  {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (big)
      for (size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
    bytes.append(raw, sizeof(T));
  }

  bool big;
  std::string eol;
  std::string bytes;
};

inline PlyData parsePlyBytes(const std::string& bytes)
{
  NullProgress progress;
  return parsePly(bytes, "test.ply", progress);
}

}  // namespace spira::test
