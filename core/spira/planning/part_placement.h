#pragma once

#include <string>

#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Where an imported part stands before it is planned: the CLI's --lower-loop, --substrate-z, --drop
// and --level-base, and the Python API's load_part options.
struct PartPlacementOptions {
  int lowerLoop = -1;  // 0-based; -1: the lowest loop
  double substrateZ = 0.0;
  bool drop = false;
  bool levelBase = false;
};

// What placePart did to the part.
struct PlacementChange {
  double dropped = 0.0;  // move along z, mm
  bool levelled = false;
  double cutZ = 0.0, removed = 0.0;  // level base: the cut plane and the height taken off, mm

  // One line per change for the terminal (empty when nothing changed).
  std::string text(double substrateZ) const;
};

// With levelBase, cuts the part level through the highest point of its base edge (level_base.h);
// with it or drop, moves the part along z so its lowest point touches the substrate (as the GUI's
// Placement > Drop to Substrate does). `report` is validated again after each change. Throws what
// levelBase and findPartTopology throw.
PlacementChange placePart(TriangleMesh& mesh, MeshReport& report, const PartPlacementOptions& options);

}  // namespace spira
