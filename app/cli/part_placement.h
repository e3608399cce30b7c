#pragma once

#include "cli_common.h"
#include "spira/io/import_service.h"

namespace spira::cli {

// Where the part stands, shared by 'plan' and 'compare': --lower-loop N (as 'info' numbers the
// loops, from 1), --substrate-z Z (mm) and --drop.
struct PartPlacement {
  int lowerLoop = -1;  // 0-based; -1: the lowest loop
  double substrateZ = 0.0;
  bool drop = false;

  static PartPlacement take(Args& args);  // throws UsageError for malformed values
  // With --drop, moves the part along z so its lowest point touches the substrate (as the GUI's
  // Placement > Drop to Substrate does) and validates it again; returns the move, mm.
  double apply(ImportedPart& part) const;
};

inline constexpr const char* kPlacementHelp =
    "  --lower-loop N     the boundary loop the part stands on, numbered from 1 as 'info' lists them\n"
    "                     (default: the lowest loop)\n"
    "  --substrate-z Z    height of the substrate plane in the part's coordinates, mm (default 0)\n"
    "  --drop             move the part along z until its lowest point touches the substrate\n";

}  // namespace spira::cli
