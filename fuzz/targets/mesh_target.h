#pragma once

#include <string>

#include "../fuzz_support.h"
#include "spira/base/progress.h"
#include "spira/io/import_service.h"

namespace spira::fuzz {

// What Spira does with a mesh reader's result once it is read (unit, geometry checks, weld,
// validation), so that a mesh target covers the whole import but the file system.
inline void finish(ImportedMesh raw, const std::string& source)
{
  NullProgress progress;
  finishImport(std::move(raw), LengthUnit::Millimetre, source, progress);
}

// A mesh reader's target: `parse(bytes, source, progress)` returns the mesh it read from the input.
template <class Parse>
int meshTarget(const uint8_t* data, size_t size, const std::string& source, Parse parse)
{
  return refusalsAllowed([&] {
    NullProgress progress;
    ImportedMesh raw;
    raw.mesh = parse(bytes(data, size), source, progress);
    finish(std::move(raw), source);
  });
}

}  // namespace spira::fuzz
