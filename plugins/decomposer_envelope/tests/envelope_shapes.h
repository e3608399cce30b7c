#pragma once

#include "spira/mesh/triangle_mesh.h"

// Open test parts for the envelope projection, built in code with known generatrices.
namespace spira::test {

// Open cylinder of radius r around +Z whose rim is cut by the plane z = h0 + x tan(slope): every
// vertex column is stretched so that the wall stays vertical. The generatrix at angle theta is
// a vertical segment of length h0 + r cos(theta) tan(slope).
TriangleMesh slopedCylinder(double r, double h0, double slope, int segments, int rings);

// Open cylinder sheared by x += z tan(lean): its horizontal sections are circles of radius r
// centred on (z tan(lean), 0). The generatrix at any angle about that axis is a straight segment
// of length h / cos(lean).
TriangleMesh obliqueCylinder(double r, double h, double lean, int segments, int rings);

// A wall of revolution with an overhanging bulge: radius `neck` from z = 0 to 50 except where a
// circular bead of radius 12 centred at r = neck + 10, z = 25 swells out around it. The bead's
// profile turns down before it turns up (it holds its lowest point z = 13 below where it leaves
// the neck, z = 18.37), so from outside the bead hides the neck between z = 13 and 18.37 (and
// between 31.63 and 37): the fold the envelope projection cannot see behind.
TriangleMesh bulgedWall(double neck, int segments);

// A tube of radius r bent into an arch: its centre line is the half circle of radius `bend` in
// the XZ plane from (bend, 0, 0) over the top to (-bend, 0, 0); both ends stand on z = 0.
TriangleMesh archTube(double bend, double r, int segments, int rings);

}  // namespace spira::test
