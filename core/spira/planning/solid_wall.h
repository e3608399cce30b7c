#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spira/mesh/mesh_report.h"
#include "spira/mesh/thin_wall.h"

namespace spira {

// A watertight part read as a thin wall: its measured thickness, the bead it is planned with and
// the mid-surface the plan runs on (docs/thin-walled-solids.md).
struct SolidWall {
  WallThickness thickness;  // mm
  double wallAreaFraction = 0.0;
  double beadWidth = 0.0;  // mm, of the process the plan was asked with
  size_t solidFaces = 0, skinFaces = 0;
  std::shared_ptr<const TriangleMesh> midSurface;
  std::vector<std::string> warnings;  // the thickness against the bead width
  // "thin-walled solid: wall 2.00 mm thick (1.90 .. 2.10 mm), bead width 5.20 mm: planned on its
  // mid-surface"
  std::string summary() const;
};

// The bead lays a wall about one bead width wide: a wall thicker than this many bead widths
// needs more material than one bead per layer gives, one thinner than kThinWallBeadRatio is
// laid much thicker than drawn.
constexpr double kThickWallBeadRatio = 1.5;
constexpr double kThinWallBeadRatio = 0.5;

// True for a part planned through its mid-surface: one watertight piece without defects.
bool isClosedSolid(const MeshReport& report);

// The analysis of a closed solid (isClosedSolid) turned into the wall Spira plans: throws
// InputError for a bulk solid, saying it is one and what to give Spira instead (the wall's
// mid-surface or one skin, never a repair). `beadWidth` in mm.
SolidWall solidWallOf(const ThinWallAnalysis& analysis, size_t solidFaces, double beadWidth);

// Throws InputError when the mid-surface (`midReport` = validateMesh(*wall.midSurface)) is not one
// wall a spiral can follow: several pieces, defects, or no free edge; it names the flat share
// of the mid-surface when there is one (a flange, a floor, a lid), the usual cause.
void requireOneWall(const SolidWall& wall, const MeshReport& midReport);

// What a closed solid is planned on: its mid-surface with its validation report.
struct SolidSurface {
  SolidWall wall;
  MeshReport report;  // validateMesh(*wall.midSurface)
};

// analyseClosedSolid, solidWallOf and requireOneWall in one: the mid-surface of a closed solid
// (isClosedSolid), or InputError saying why it has none Spira can plan.
SolidSurface plannableMidSurface(const TriangleMesh& solid, double beadWidth);

// The bead-width warnings alone (empty when the wall is within the rule's range).
std::vector<std::string> beadWidthWarnings(const WallThickness& thickness, double beadWidth);

}  // namespace spira
