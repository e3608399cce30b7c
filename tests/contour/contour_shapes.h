#pragma once

#include <vector>

#include "spira/mesh/triangle_mesh.h"

// Meshes and analytic fields for the contour tests, built in code.
namespace spira::test {

// value = scale * z at every vertex.
std::vector<double> heightField(const TriangleMesh& mesh, double scale = 1.0);
// Geodesic distance from the base circle on a hemisphere of radius R centred on the origin:
// R * (pi/2 - polar angle) = R * latitude.
std::vector<double> hemisphereDistance(const TriangleMesh& mesh, double radius);
// The two meshes side by side in one (faces of `b` renumbered).
TriangleMesh merged(const TriangleMesh& a, const TriangleMesh& b);
TriangleMesh translated(TriangleMesh m, const Vec3& offset);
// A flat tuning fork in the z = 0 plane, faces up: x in [-3, 3], y in [0, 10], 1 mm grid cells,
// with the cells x in [-1, 1], y in [5, 10] cut out (two prongs above y = 5).
TriangleMesh flatFork();
// Distance from p to the regular n-gon of circumradius r around the Z axis in the plane z = p.z,
// vertices at angles 2 pi j / n.
double distanceToPolygon(const Vec3& p, double r, int n);

}  // namespace spira::test
