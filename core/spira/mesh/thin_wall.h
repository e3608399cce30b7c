#pragma once

#include <string>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// What a closed (watertight) solid is, seen as a WAAM wall. See docs/thin-walled-solids.md.
enum class SolidKind {
  ThinWalled,  // two skins facing each other a thin, consistent distance apart
  Bulk,        // a solid body (a vase-mode print body, a block): no wall to lay a bead along
};

// Area-weighted wall thickness, mm, over the "wall faces": faces whose inward ray meets the
// opposite skin facing back within kRimFactor x the median (the end annuli and flange sides,
// whose ray runs along the wall, are left out).
struct WallThickness {
  double median = 0.0;
  double thinnest = 0.0;  // 2nd area percentile: the thinnest 2 % of the area is meshing noise
  double thickest = 0.0;  // 98th area percentile
};

struct ThinWallAnalysis {
  SolidKind kind = SolidKind::Bulk;
  WallThickness thickness;
  double wallAreaFraction = 0.0;  // share of the surface area made of wall faces
  double diagonal = 0.0;          // of the bounding box, mm
  std::string reason;             // why it is thin-walled or bulk, in plain words
  // Thin-walled only: one skin (the larger), each vertex moved inward by half the local
  // thickness. Open, outward-oriented like the solid, its free edges at the wall's ends.
  TriangleMesh midSurface;
  size_t skinFaces = 0;  // faces of the solid kept as the skin
};

// A thin wall is at most this share of the part's bounding-box diagonal thick over most of its
// area; a bulk body is about as thick as it is wide.
constexpr double kThinWallMaxRelativeThickness = 0.1;
// A face whose inward ray runs further than this many median thicknesses crosses the wall along
// its length: a rim (an end annulus), not a skin.
constexpr double kRimFactor = 3.0;

// Measures the wall thickness of a closed, outward-oriented mesh by casting a ray from each face's
// centroid along its inward normal to the opposite skin, classifies it and, when it is thin-walled,
// extracts the mid-surface. Callers pass one watertight, consistently oriented component
// (validateMesh finds no boundary loop and no defect); one oriented inside out is measured turned
// the right way. Other meshes come out Bulk or with a mid-surface of their own shape.
ThinWallAnalysis analyseClosedSolid(const TriangleMesh& mesh);

}  // namespace spira
