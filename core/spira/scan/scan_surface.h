#pragma once

#include <string>

#include "spira/mesh/triangle_mesh.h"
#include "spira/scan/point_cloud.h"

namespace spira {

// A scanned plate or warped sheet as a surface to build on: the scan seen from above (+z), gridded in
// cells of `cell` mm, each cell's height the median of the points in it (noise and stray points do not
// move a median), cells the scan missed filled from their neighbours where they are surrounded, and the
// cell centres meshed into triangles facing up. Throws InputError when the scan is not seen from above
// (a cell holding points more than `maxSpread` mm apart in height: walls, a pipe) or covers too little.
TriangleMesh heightFieldFromScan(const PointCloud& scan, double cell, double maxSpread = 3.0);

// The cell size for a scan: twice its mean point spacing seen from above, at least 0.5 mm.
double heightFieldCell(const PointCloud& scan);

}  // namespace spira
