#pragma once

#include <string>

#include "spira/mesh/triangle_mesh.h"
#include "spira/planning/planner.h"

namespace spira::test {

// The source's quarter torus (004_bd0df31205c0c3c0.txt §2.3): bend radius 50, tube radius 15, about 2 mm
// edges, base ring in z = 0.
TriangleMesh quarterTorus();

// Plans `mesh` with decomposer.constant_distance, the nominal height `h` inside h_min .. h_max, and the
// decomposer's own values (output, end, stagger, guide) as given; empty keeps the default.
PlanOutput planTube(const TriangleMesh& mesh, double h, double hMin, double hMax,
                    const std::string& output = {}, const std::string& end = {},
                    const std::string& guide = {}, int points = 0);

// Every point the deposit check flags lies under the same layer's bead at a fold of a quarter torus's
// layer (a kink of more than 90 deg, on the outer side of the bend): the kink the source reports, which
// folds the layer over itself near the top of the bend (docs/tubes.md). Returns how many there are.
size_t expectFlagsOnlyAtFolds(const PlanOutput& plan, double bendRadius);

// planTube on a substrate mesh (in the part's frame) instead of the plate.
PlanOutput planTubeOn(const TriangleMesh& mesh, const TriangleMesh& substrate, double h, double hMin,
                      double hMax, const std::string& output, int points);

// The distance from p to the closed polyline `loop`, over all its segments.
double distanceToClosed(const Vec3& p, const std::vector<Vec3>& loop);

// The same part planned by another strategy, with the same window.
PlanOutput planWith(const std::string& decomposerId, const TriangleMesh& mesh, double h, double hMin,
                    double hMax, int points);

}  // namespace spira::test
