#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/substrate_surface.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

// What the check needs besides the trajectory: the substrate plane and the process window.
struct DepositCheckSettings {
  double substrateZ = 0.0;  // part frame, mm
  // A substrate that is not the plane z = substrateZ (a pipe, a curved plate): the first beads rest on it.
  std::shared_ptr<const SubstrateSurface> substrate;
  double hMin = 1.8, hMax = 2.2;
  double tolerance = 0.01;  // mm on both window bounds
  double beadWidth = 4.0;   // mm
  // Largest uncovered share of the surface a feasible plan may leave (the mesh's own sampling
  // leaves a few samples at the base's corners just beyond the cover radius).
  double maxUncoveredFraction = 0.005;
};

enum class DepositDefect { BelowDeposit, Thin, Thick, Unsupported, Jump };
const char* depositDefectName(DepositDefect kind);  // "below_deposit", "thin", ...

struct DepositFlag {
  size_t point = 0;  // trajectory index
  DepositDefect kind = DepositDefect::Unsupported;
  // Measured height (jump: segment length); unsupported with nothing within the report's
  // searchDepth below: inf.
  double height = 0.0;
  Vec3 position = Vec3::Zero();
};

struct DepositCheckReport {
  size_t pointsChecked = 0;  // arc-on points
  // Measured, over every point with material below it (flagged ones included), mm.
  double heightMin = 0.0, heightMax = 0.0, heightMean = 0.0;
  // Largest |measured - planned| over points within the window, mm: how far the planned height
  // channel is from what the path itself lays.
  double plannedDifferenceMax = 0.0;
  size_t counts[5] = {0, 0, 0, 0, 0};  // per DepositDefect
  std::vector<DepositFlag> flags;      // in trajectory order
  double jumpLength = 0.0;             // the largest step with the arc on still accepted, mm (first run)
  double searchDepth = 0.0;            // how far below a point material is looked for, mm

  bool coverageChecked = false;
  double surfaceArea = 0.0, uncoveredArea = 0.0;  // mm^2
  double largestGap = 0.0;                        // largest surface-to-path distance, mm
  Vec3 largestGapAt = Vec3::Zero();
  double coverRadius = 0.0;  // mm

  bool feasible = false;
  size_t count(DepositDefect kind) const { return counts[static_cast<int>(kind)]; }
  double uncoveredFraction() const { return surfaceArea > 0.0 ? uncoveredArea / surfaceArea : 0.0; }
  // One line a user reads: what failed, how many points, the first of them.
  std::string summary() const;
};

// Decides from the trajectory alone whether the deposits it describes can be laid: every arc-on
// point is supported by earlier material or the substrate at a distance along its build direction
// inside [h_min - tol, h_max + tol], no arc-on jump, and (with `surface`) the surface covered.
// The rules are in docs/deposit-check.md. `surface` may be null.
DepositCheckReport checkDeposits(const Trajectory& path, const TriangleMesh* surface,
                                 const DepositCheckSettings& settings, Progress& progress);

}  // namespace spira
