#pragma once

#include <functional>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Analytic test and sample shapes, in mm, outward-facing, welded (shared vertices), consistently
// oriented, without degenerate faces. Vertices lie on the analytic surface to rounding, the first
// vertex of every ring at angle 0 (+X), and quarter-turn vertices have exact zero coordinates.
// `segments` is the count around the axis, `rings` along it. Invalid sizes throw InputError.

// Thin-walled open cylinder (a tube surface) around +Z from z = 0 to z = height.
TriangleMesh makeOpenCylinder(double radius, double height, int segments, int rings);
// Open truncated cone: radius r0 at z = 0, r1 at z = height.
TriangleMesh makeOpenCone(double r0, double r1, double height, int segments, int rings);
// Hemisphere (dome) of radius R centred on the origin, open at z = 0, pole at (0,0,R).
// `rings` counts latitude bands from the base to the pole.
TriangleMesh makeHemisphere(double radius, int segments, int rings);
// A surface of revolution through the profile points (r_i, z_i), i = 0..n-1, from bottom to top.
// A last point with r = 0 closes the top at the axis with one pole vertex (a first point with
// r = 0 closes the bottom the same way). Faces look to the right of the profile's direction in
// the (r, z) half-plane: outwards for a profile running up the outside of the part.
TriangleMesh makeRevolved(const std::vector<Eigen::Vector2d>& profile, int segments);
// A solid of revolution: the closed profile (r_i, z_i) with r > 0 (the last point joins the first,
// without repeating it), faces to the right of its direction as in makeRevolved: a profile running
// up the outside and down the inside (clockwise in the (r, z) half-plane) faces outwards.
TriangleMesh makeRevolvedSolid(const std::vector<Eigen::Vector2d>& closedProfile, int segments);
// A thin-walled tube as a solid (watertight, as CAD exports it): outer skin of `outerRadius`, inner
// skin of `innerRadius`, from z = 0 to z = height, joined by flat end annuli. `rings` bands
// along each skin, one across each annulus.
TriangleMesh makeTubeSolid(double outerRadius, double innerRadius, double height, int segments, int rings);
// A bent tube: a section of torus whose guide is the arc of radius `bendRadius` from the origin up
// (g(t) = (R cos t - R, 0, R sin t), t from 0 to `angle` rad), with a circular profile of `radius`;
// its base ring lies in z = 0 around +Z. `segments` round the profile, `rings` along the bend.
TriangleMesh makeBentTube(double bendRadius, double radius, double angle, int segments, int rings);
// An open tube sampled from a surface at(u, v), u from 0 (base ring) to 1 (top ring) in `rings` rows and
// v round it in `segments`, faces wound as v and u grow (outward when v turns counter-clockwise seen from
// where u grows).
TriangleMesh makeTubeSurface(const std::function<Vec3(double u, double v)>& at, int segments, int rings);
// An open cylinder of `radius` about the x, y or z axis (`axis`) through the origin, `length` long and
// centred there, with edges of about 2 mm (longer on a pipe that would take more than about 200,000
// triangles): a pipe to build a feature on.
TriangleMesh makePipeAbout(double radius, char axis, double length);
// The same bent tube added onto a cylinder x^2 + z^2 = cylinderRadius^2 (axis y): each profile point
// starts where it leaves the cylinder (004_bd0df31205c0c3c0.txt Eq. 2.17-2.19, the source's torus feature
// on a 64 mm pipe), so the base edge lies on the cylinder.
TriangleMesh makeTorusOnCylinder(double bendRadius, double radius, double cylinderRadius, double angle,
                                 int segments, int rings);
// A closed regular tetrahedron (4 faces) centred on the origin, useful as the smallest watertight mesh.
TriangleMesh makeTetrahedron(double edge);
// `segments` (at least 3) so that the edges round a circle of `radius` are about `edge` long.
int segmentsForEdge(double radius, double edge);
// `rings` (at least 1) so that the edges along a profile of `length` are about `edge` long.
int ringsForEdge(double length, double edge);

}  // namespace spira
