#pragma once

#include <functional>

#include "spira/mesh/triangle_mesh.h"

// Closed test shapes that no primitive builds (a Y-shaped tube), made in code from an implicit
// function by marching tetrahedra.
namespace spira::test {

// The surface f = 0 of `f` (negative inside) sampled on a grid of `cell` mm over `box`, outward
// facing, welded (vertices shared along grid edges) and manifold: each cube is cut into six
// tetrahedra around its main diagonal, the same way in every cube, so neighbouring cubes agree
// on their shared faces. `box` must enclose the shape with a margin of at least one cell.
TriangleMesh meshImplicit(const std::function<double(const Vec3&)>& f, const BoundingBox& box, double cell);

// Signed distance to a capsule (segment a-b, radius r).
double capsule(const Vec3& p, const Vec3& a, const Vec3& b, double r);

// A Y: a trunk from (0, 0, -length) to the origin and two arms from the origin rising at
// +-armAngle from vertical in the XZ plane, all of tube radius r, each `length` long.
double yShape(const Vec3& p, double length, double r, double armAngle);

}  // namespace spira::test
