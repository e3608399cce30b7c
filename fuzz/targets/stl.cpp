// The STL reader (binary and ASCII) and the import steps after it.
#include "mesh_target.h"
#include "spira/io/stl_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::meshTarget(data, size, "fuzz.stl", [](auto bytes, auto& source, auto& progress) {
    return spira::parseStl(bytes, source, progress).soup;
  });
}
