#pragma once

#include "spira/base/progress.h"
#include "spira/path/spiral_report.h"
#include "spira/path/spiral_settings.h"
#include "spira/path/trajectory.h"

namespace spira {

// Discretises generatrices into one continuous spiral with a locally modulated deposit (thesis
// 000_dbb97c2716e10cc3.txt §3.2.3-3.3.4; docs/method.md §5):
//  1. start-up: n_steplayer revolutions of ramps (StartupProfile) that remove the height step at
//     the spiral start;
//  2. modulated phase: the length l_i each generatrix has left (after the start-up and, with
//     Termination::Ramps, the termination) is cut into n_layer equal steps d_i = l_i / n_layer
//     (LayerMode), so the deposit varies point by point and anticipates the upper edge;
//  3. termination (Termination::Ramps): the start-up mirrored, so the last revolution lies exactly
//     on the end of every generatrix: the upper edge of an open part, the closure point of a
//     closed one.
// With StartupTransition::UniformHelix (default) the ramps are sized for the modulated phase's step
// at the seam, so the spiral climbs d / n at every point, the seam included.
// Every point lies on a generatrix, placed by arc length from its base (the generatrix's first
// point): revolution k of generatrix i sits at the sum of its steps so far, so a point marks the top
// of the deposit laid there. Points are joined revolution by revolution, P(0,k) .. P(n-1,k),
// P(0,k+1), ..., into one polyline: one arc on, one arc off. The ramps are indexed by u = i/(n-1),
// so generatrices should be spread about evenly around the part.
// Closed parts end on the closure point once: the trailing revolutions shorter than
// SpiralSettings::minRevolutionLength (the last one at least, which is the closure point repeated
// n times) are replaced by that single point.
// Each point gets its frame (spiral_frames.h), its true deposit height h = d cos(theta) (d the
// chord of its step, computeDepositHeights) and the revolution and generatrix it belongs to; the
// report checks feasibility (Eq. 3.6 and 3.15) on every point. Where the layers lean on the
// generatrices (cos(theta) < 1 - 1e-4: a tilted or non-planar base such as a branch's saddle cut, a
// non-planar upper edge, a converging dome) the steps are stretched point by point, per generatrix
// and per revolution, by 1 / cos(theta): the ramps so that their true heights stay nominal
// (docs/method.md M14, M18), the modulated revolutions then scaled back so that each generatrix still lays
// its layers in its modulated length, at one true height. Stretching moves the points and so changes theta:
// the stretch is iterated to its fixed point (damped, smooth between neighbouring generatrices, at most 12
// layouts), and the layout with the fewest window violations is kept. The seam goes on the generatrix that
// leans least along the travel (seam_placement.h); points keep the given generatrix numbers. See
// docs/spiral-heights.md.
//
// Throws InputError for unusable input (see StartupProfile, spiral_input.h) and for generatrices
// too short to hold the start-up, the termination and one layer of h_min. An infeasible window is
// not an error: the result says feasible = false and lists the violations.
SpiralResult buildSpiral(const Generatrices& generatrices, const SpiralSettings& settings,
                         Progress& progress);

}  // namespace spira
