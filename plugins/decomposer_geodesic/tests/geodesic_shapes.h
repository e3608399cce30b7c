#pragma once

#include <functional>
#include <vector>

#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/decomposer.h"

namespace spira::test {

// Parts for the geodesic decomposer's tests, made in code with known geometry.

// A tube of radius r(alpha, z) around +Z, from z = 0 to z = top(alpha), `segments` around and
// `rings` up; outward faces. The vertices of ring j sit at z = top(alpha) * j / rings.
TriangleMesh makeTube(const std::function<double(double alpha, double z)>& radius,
                      const std::function<double(double alpha)>& top, int segments, int rings);

// The radius of the bumped cylinder used by the coverage tests: R plus a Gaussian bump of height
// `bump` centred at angle 0 and height zc (widths sigmaAngle rad and sigmaZ mm).
struct Bump {
  double R = 30.0, bump = 6.0, zc = 30.0, sigmaAngle = 0.35, sigmaZ = 12.0;
  double radius(double alpha, double z) const;
};

// The mesh, its report, and a DecomposeInput over them (lower loop first, upper loop if any).
struct Part {
  TriangleMesh mesh;
  MeshReport report;
  DecomposeInput input() const;
};
Part makePart(TriangleMesh mesh);

// Angle about +Z of p, in [0, 2 pi).
double angleOf(const Vec3& p);
double polylineLength(const std::vector<Vec3>& line);

// Distance from p to the surface r = radius(alpha, z) (dense search, then refinement, near p).
double distanceToTube(const Vec3& p, const std::function<double(double, double)>& radius);

}  // namespace spira::test
