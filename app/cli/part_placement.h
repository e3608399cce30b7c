#pragma once

#include "cli_common.h"
#include "spira/io/import_service.h"
#include "spira/planning/part_placement.h"

namespace spira::cli {

// Where the part stands, shared by 'plan' and 'compare': --lower-loop N (as 'info' numbers the
// loops, from 1), --substrate-z Z (mm), --level-base and --drop.
struct PartPlacement {
  int lowerLoop = -1;  // 0-based; -1: the lowest loop
  double substrateZ = 0.0;
  bool drop = false;
  bool levelBase = false;

  static PartPlacement take(Args& args);  // throws UsageError for malformed values
  // placePart (spira/planning/part_placement.h) with these flags.
  PlacementChange apply(ImportedPart& part) const;
};

inline constexpr const char* kPlacementHelp =
    "  --lower-loop N     the boundary loop the part stands on, numbered from 1 as 'info' lists them\n"
    "                     (default: the lowest loop)\n"
    "  --substrate-z Z    height of the substrate plane in the part's coordinates, mm (default 0)\n"
    "  --drop             move the part along z until its lowest point touches the substrate\n"
    "  --level-base       cut the part level through the highest point of its base edge (a scan cut\n"
    "                     at a slant), then drop it onto the substrate\n";

}  // namespace spira::cli
