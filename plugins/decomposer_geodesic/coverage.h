#pragma once

#include <optional>
#include <vector>

#include "base_ring.h"
#include "generatrix_line.h"
#include "spira/base/progress.h"
#include "surface_locator.h"

namespace spira::geodesic {

// Thesis Eq. 3.8-3.9 between two neighbouring generatrices resampled to the same count: the strip
// psi of rungs joining their points at equal arc-length fractions, and eps = the largest distance
// from psi to the surface. The strip is sampled at the rung midpoints, the points of psi farthest
// from both generatrices (its corner vertices lie on the surface, so their distance says nothing);
// the distance is to the closest point of the surface (the continuous form of the thesis's nearest
// vertex of S', which would read half an edge length on a perfectly covered part). Where
// geodesics take a shortcut round a bulge, the rungs across the bulge run under it and eps grows.
struct CoverageGap {
  double error = 0.0;  // eps, mm
  size_t sample = 0;   // the rung that realised it
};
CoverageGap coverageGap(const GeneratrixLine& a, const GeneratrixLine& b, const SurfaceLocator& locator);

// What a fill-in generatrix needs: the surface, the base and the end (upper edge or closure point).
struct FillInContext {
  const GeodesicMesh& mesh;
  const SurfaceLocator& locator;
  const BaseRing& base;
  const BoundaryLoop* upper = nullptr;  // open parts
  std::optional<SurfacePoint> closure;  // closed parts
  size_t samples = 2;                   // points per generatrix
};

// The fill-in generatrix between a and b (thesis 000_dbb97c2716e10cc3.txt §3.3.2.2): their median curve
// projected on the surface (each point onto its closest surface point, i.e. along the vector (v, v') that
// gave the error), starting on the base at the angle halfway between theirs and ending on the upper edge (its
// closest point) or at the closure point.
GeneratrixLine fillInBetween(const GeneratrixLine& a, const GeneratrixLine& b, const FillInContext& context);

struct CoverageResult {
  std::vector<GeneratrixLine> lines;
  size_t fillIns = 0;
  int rounds = 0;         // rounds that inserted generatrices
  double maxError = 0.0;  // largest eps left between neighbours, mm
  size_t worstPair = 0;   // lines[worstPair] and the next one (cyclically)
  bool converged = true;  // every eps <= the tolerance
};

// Checks every pair of neighbours (the lines form a loop around the part) and inserts a fill-in
// generatrix wherever eps > `tolerance`, then checks the new pairs, for at most `maxRounds` rounds
// and `maxLines` lines in all. The lines must all have context.samples points.
CoverageResult fillCoverageGaps(std::vector<GeneratrixLine> lines, const FillInContext& context,
                                double tolerance, int maxRounds, size_t maxLines, Progress& progress);

}  // namespace spira::geodesic
