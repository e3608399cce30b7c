#pragma once

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Analytic test and sample shapes, in mm, outward-facing, welded (shared vertices).
// `segments` is the count around the axis, `rings` along it.

// Thin-walled open cylinder (a tube surface) around +Z from z = 0 to z = height.
TriangleMesh makeOpenCylinder(double radius, double height, int segments, int rings);
// Open truncated cone: radius r0 at z = 0, r1 at z = height.
TriangleMesh makeOpenCone(double r0, double r1, double height, int segments, int rings);
// Hemisphere (dome) of radius R centred on the origin, open at z = 0, pole at (0,0,R).
// `rings` counts latitude bands from the base to the pole.
TriangleMesh makeHemisphere(double radius, int segments, int rings);
// A surface of revolution through the profile points (r_i, z_i), i = 0..n-1, from bottom to top.
// A last point with r = 0 closes the top at the axis.
TriangleMesh makeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments);
// A closed tetrahedron (4 faces), useful as the smallest watertight mesh.
TriangleMesh makeTetrahedron(double edge);
// Picks `segments` and `rings` so that the mean edge length is about `edge` on the shapes above.
int segmentsForEdge(double radius, double edge);

}  // namespace spira
