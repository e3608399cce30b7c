// The Wavefront OBJ reader and the import steps after it.
#include "mesh_target.h"
#include "spira/io/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::meshTarget(data, size, "fuzz.obj", [](auto bytes, auto& source, auto& progress) {
    return spira::parseObj(bytes, source, progress).mesh;
  });
}
