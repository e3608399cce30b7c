#pragma once

#include <string>
#include <vector>

#include "spira/scan/point_cloud.h"

namespace spira {

// The cloud as a binary little-endian PLY (float x y z, nx ny nz when it has normals, and one float
// property `scalarName` per point when `scalar` is given), as CloudCompare and ParaView read it.
std::string pointCloudPly(const PointCloud& cloud, const std::vector<double>* scalar = nullptr,
                          const std::string& scalarName = "deviation");

}  // namespace spira
