#pragma once

#include <string>
#include <vector>

#include "spira/planning/planner.h"

namespace spira {

// A junction's crotch is a saddle of the part's height: the wall is level there, so the rings that
// cross it (the trunk's last ones, climbing into the saddle, and the branches' first) lie farther
// apart along the wall than any bead is high, or over the hollow under the crotch. No window or
// strategy lays a bead on a bead there. This finds the deposit check's flags around each crotch.
struct CrotchFlags {
  Vec3 crotch = Vec3::Zero();  // the saddle vertex
  size_t flagged = 0;          // flagged points within the radius
  size_t midAir = 0;           // of them, with nothing within the check's search depth below
  double thickest = 0.0;       // mm, the largest measured height of the others (0: none)
};

// The flags within `radius` of each crotch of a branching plan (<= 0: 4 bead widths), crotches
// without flags left out; empty for a mono-branch plan.
std::vector<CrotchFlags> flagsAtCrotches(const PlanOutput& plan, double beadWidth, double radius = 0.0);

// One sentence a user reads: where each crotch is, what its flagged points do, and why.
std::string crotchText(const std::vector<CrotchFlags>& crotches, size_t flaggedInAll, double hMax);

}  // namespace spira
