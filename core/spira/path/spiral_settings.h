#pragma once

#include "spira/base/units.h"
#include "spira/path/process_model.h"
#include "spira/path/startup_profile.h"

namespace spira {

// How many revolutions the modulated phase gets (after the start-up, before the termination).
enum class LayerMode {
  // Thesis Eq. 3.14: n = floor(min(L) / h_min). The shortest generatrix gets about h_min, the
  // mean deposit falls below h.
  Floor,
  // Centres the mean deposit on h (000_dbb97c2716e10cc3.txt §4.3: "the mean is brought back to h"). n is the
  // count
  // whose mean step mean(L) / n lies closest to h (floor or ceil of mean(L) / h, i.e. round()
  // except where 1/n's curvature tips a near-half case), then clamped into the counts for which
  // every step d_i = l_i / n lies in the window, [ceil(max L / h_max), floor(min L / h_min)],
  // when that range is not empty. When it is empty no count fits and the centred one is kept; the
  // report then says the plan is infeasible.
  Centered,
};

// How the spiral ends.
enum class Termination {
  // The start-up mirrored (see StartupProfile): the modulated phase keeps the helix the start-up
  // built all the way up, and the last j_full + 2 revolutions level it onto the upper edge (or the
  // closure point). Ramps and termination take the same length on every generatrix, so on a
  // cylinder every modulated step is the same.
  Ramps,
  // The thesis as written (000_dbb97c2716e10cc3.txt §3.3.3): no termination revolutions; d_i = l_i / n
  // absorbs the start-up
  // climb over the whole build. The last revolution still lies on the upper edge, but the seam
  // rise grows to about d over the build, and the seam points' true heights shrink with it.
  Absorb,
};

struct SpiralSettings {
  double h = 2.0;     // nominal deposit height, mm
  double hMin = 1.8;  // thinnest deposit the process lays, mm
  double hMax = 2.2;  // thickest deposit, mm
  LayerMode layerMode = LayerMode::Centered;
  // UniformHelix by default: with ToNominal every seam rises d - 0.9 h in one segment (at ±10 %;
  // 0.1 h in centred mode), and its true height d cos(theta) leaves the window wherever
  // neighbouring generatrices are close (1-degree dome: within about r = 11 h of the closure point).
  StartupTransition startupTransition = StartupTransition::UniformHelix;
  Termination termination = Termination::Ramps;
  // Eq. 3.15 tolerance, as a fraction of h: a height counts as outside the window only beyond
  // [h_min - tol h, h_max + tol h]. The default 0.5 % (0.01 mm at h = 2 mm) is far below what a WAAM
  // process resolves; it absorbs the cos(theta) = 1 - x^2 / 2 of a path that climbs with slope x on
  // steps placed exactly at h_min (a uniform helix of radius r climbs x = h / (2 pi r): 0.5 % at
  // r = 1.6 h).
  double heightTolerance = 0.005;
  // Closed parts: trailing revolutions shorter than this (mm) are replaced by the closure point
  // alone, so the path does not end with many copies of it. The default, pi times the default bead
  // width, folds the rings narrower than the bead; 0 means h, which folds only the last revolution
  // (the closure point itself).
  double minRevolutionLength = kPi * kDefaultBeadWidth;
};

}  // namespace spira
