// The STEP front-end: what Spira's own process reads when a CAD file (STEP, IGES, BREP) is
// imported. OpenCASCADE runs in the spira-import helper (isolated_import.h); its stream of frames
// comes back through wire::Reader, which must refuse any byte sequence without crashing or
// allocating from an unchecked length, however the bytes are split across reads, and the
// mesh it passes goes through the same checks as any other import. The first
// input byte chooses the read size.
#include <algorithm>

#include "../fuzz_support.h"
#include "mesh_target.h"
#include "spira/io/import_wire.h"
#include "spira/io/step_tokens.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  if (size == 0) return 0;
  spira::fuzz::refusalsAllowed(
      [&] { spira::checkStepTokens(spira::fuzz::bytes(data, size), "fuzz.step", 64); });
  const size_t chunk = 1 + data[0] % 64;
  const char* stream = reinterpret_cast<const char*>(data + 1);
  const size_t length = size - 1;
  spira::wire::Reader reader;
  spira::NullProgress progress;
  try {
    for (size_t at = 0; at < length; at += chunk)
      reader.feed(stream + at, std::min(chunk, length - at), progress);
  } catch (const spira::InternalError&) {
    // The documented refusal: the helper is Spira's own, so a stream it cannot have written is a bug
    // report, which the import then names with the file.
    return 0;
  }
  if (!reader.complete() || !reader.mesh()) return 0;
  return spira::fuzz::refusalsAllowed([&] { spira::fuzz::finish(std::move(*reader.mesh()), "fuzz.step"); });
}
