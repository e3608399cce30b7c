#pragma once

#include <string>

#include "spira/base/progress.h"
#include "spira/io/obj_reader.h"

namespace spira::test {

inline ObjData parseObjBytes(const std::string& bytes)
{
  NullProgress progress;
  return parseObj(bytes, "test.obj", progress);
}

// The corners of the unit cube [0, 1]^3, numbered 1..8 as OBJ counts them.
inline const std::string kCubeVertices =
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n";

}  // namespace spira::test
