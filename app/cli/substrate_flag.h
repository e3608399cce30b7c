#pragma once

#include <memory>
#include <string>

#include "part_loading.h"
#include "spira/document/substrate.h"

namespace spira::cli {

// --substrate FILE|cylinder:RADIUS[,AXIS[,LENGTH]]: the surface the part is built on, in the part file's
// coordinates. A mesh file (STL, OBJ, PLY, STEP: a pipe, a curved plate, a previous part) is imported with
// the part's import flags; a cylinder is RADIUS mm about the axis x, y (default) or z through the origin,
// LENGTH mm long (default 8 RADIUS) centred on it. Throws UsageError for a malformed cylinder.
Substrate substrateFromFlag(const std::string& value, ImporterFlags& importer, Progress& progress);

// --substrate-scan SCAN is passed on as this prefix and the scan's path: a scanned plate, read as a
// height field (scan_surface.h) after its stray points are removed.
inline constexpr const char* kScanPrefix = "scan:";

// The flag's line in the usage texts.
inline constexpr const char* kSubstrateFlagHelp =
    "  --substrate FILE|cylinder:R[,AXIS[,LENGTH]]\n"
    "                     build on a surface, not the plate: a mesh (a pipe, a curved plate, a previous\n"
    "                     part) or a cylinder of radius R mm about the x, y (default) or z axis through the\n"
    "                     origin; the part's base edge must lie on it, in the part file's coordinates\n"
    "  --substrate-scan SCAN\n"
    "                     build on a scanned plate (a point cloud of its top surface, docs/scans.md): the "
    "first\n"
    "                     beads are measured down to the surface the scan describes\n";

}  // namespace spira::cli
