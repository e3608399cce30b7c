// The PLY reader (ASCII, both binary byte orders) and the import steps after it.
#include "mesh_target.h"
#include "spira/io/ply_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::meshTarget(data, size, "fuzz.ply", [](auto bytes, auto& source, auto& progress) {
    return spira::parsePly(bytes, source, progress).mesh;
  });
}
