#pragma once

#include <cstddef>
#include <vector>

#include "spira/path/trajectory.h"

namespace spira {

enum class SpiralPhase { StartUp, Modulated, Termination, Closure };
const char* spiralPhaseName(SpiralPhase phase);  // "start_up", "modulated", "termination", "closure"

// A trajectory point whose true deposit height lies outside the tolerated window (Eq. 3.15).
struct HeightViolation {
  size_t point = 0;  // index in the trajectory
  int revolution = 0;
  int generatrix = 0;
  double height = 0.0;  // mm
  SpiralPhase phase = SpiralPhase::Modulated;
  bool aboveWindow = false;  // true: thicker than h_max, false: thinner than h_min
};

// Thesis Eq. 3.6: (max(G) - min(G)) / n_layer <= h_max - h_min, i.e. the per-revolution steps of
// the generatrices cannot differ by more than the window is wide.
struct LengthCriterion {
  double lengthMin = 0.0, lengthMax = 0.0;  // mm
  int nLayers = 0;
  double stepSpread = 0.0;  // (lengthMax - lengthMin) / nLayers, mm
  double window = 0.0;      // h_max - h_min, mm
  bool ok = false;
};

struct SpiralReport {
  int nStartupRevolutions = 0;   // n_steplayer
  int nLayers = 0;               // n_layer: revolutions of the modulated phase
  int nEndRevolutions = 0;       // termination revolutions (0 with Termination::Absorb)
  int nRevolutions = 0;          // all of them, the closing one included
  int collapsedRevolutions = 0;  // closed parts: trailing revolutions replaced by the closure point
  size_t nPoints = 0;
  int pointsPerRevolution = 0;

  double generatrixLengthMin = 0.0, generatrixLengthMax = 0.0;  // full lengths G, mm
  double modulatedLengthMin = 0.0, modulatedLengthMax = 0.0;    // L: what the modulated phase divides
  double stepMin = 0.0, stepMax = 0.0;                          // d_i = l_i / n_layer, mm
  // Rise along the generatrices from the last point of a modulated revolution to the first point of
  // the next: d_0 - climb (StartupProfile); c / n for a uniform helix, mm.
  double seamStep = 0.0;

  // True deposit heights h = d cos(theta), d the chord of the step, over the modulated phase (the
  // thesis's H_depot), mm.
  double heightMin = 0.0, heightMax = 0.0, heightMean = 0.0;
  // The same over the start-up and termination ramps, which use the whole window to climb from the
  // substrate and level the top (0 when the spiral has no ramp point).
  double rampHeightMin = 0.0, rampHeightMax = 0.0;
  double pathLength = 0.0;  // mm
  double maxJump = 0.0;     // longest segment between consecutive points, mm
  // Largest rise along b over a seam segment (last point of a revolution to the first of the next),
  // mm: the start-up's first seams and the termination's last ones climb up to about h_min there.
  double seamRiseMax = 0.0;

  LengthCriterion lengthCriterion;        // Eq. 3.6 on L with the n_layer used
  LengthCriterion thesisLengthCriterion;  // Eq. 3.6 as printed: on G with n = floor(min G / h_min)

  // Eq. 3.15 (corrected: h_min <= h <= h_max) with the tolerance below, on EVERY point: start-up,
  // modulated phase, termination and closure point. Feasible means Eq. 3.6 holds and no point
  // violates Eq. 3.15. (The thesis checks H_depot, the modulated phase only; its count is kept in
  // modulatedViolations.) Ramp revolutions use nominal steps inside the window by construction, and
  // the seam frames (computeFrames) keep their true heights there.
  bool feasible = false;
  double h = 0.0, hMin = 0.0, hMax = 0.0;  // the window the spiral was planned for, mm
  double heightTolerance = 0.0;            // mm
  std::vector<HeightViolation> violations;
  size_t modulatedViolations = 0;
  // Closed parts: arc length along generatrix 0 from the last kept revolution to the closure point,
  // mm. The bead laid on that last ring (at least pi x bead width long) covers it sideways, so the
  // closure point takes the last ring's deposit height rather than this length.
  double closureGap = 0.0;

  bool normalsEstimated = false;  // the generatrices came without normals
  bool normalsFlipped = false;    // normals were reversed so that b = n x t points up the generatrices
};

struct SpiralResult {
  Trajectory trajectory;
  SpiralReport report;
};

}  // namespace spira
