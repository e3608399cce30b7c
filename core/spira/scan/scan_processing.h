#pragma once

#include <cstddef>
#include <vector>

#include "spira/scan/point_cloud.h"

namespace spira {

// Cleaning a raw scan (PCL): a voxel grid keeps one point per cell (the centroid of those in it), then
// statistical outlier removal drops the points whose mean distance to their neighbours lies more than
// `outlierStddev` standard deviations above the cloud's (the stray returns of a laser line scanner).
struct ScanFilterSettings {
  double voxelMm = 0.0;        // cell size; 0 keeps every point
  int outlierNeighbours = 16;  // neighbours the mean distance is taken over
  double outlierStddev = 3.0;  // 0 keeps every point
};

struct ScanFilterReport {
  size_t read = 0, afterVoxel = 0, outliers = 0, kept = 0;
};

// Normals present are kept (averaged per voxel and normalised). Throws InputError for bad settings.
PointCloud filterScan(const PointCloud& cloud, const ScanFilterSettings& settings,
                      ScanFilterReport* report = nullptr);

// Estimates a unit normal per point from its `neighbours` nearest points (PCL, a plane fit), oriented
// away from the cloud's centroid axis through `inside` (a point inside the part: its normals then
// point out of the material). Replaces any normals the cloud had.
void estimateNormals(PointCloud& cloud, int neighbours, const Vec3& inside);

// For each query, the index of the nearest of `points` (PCL's k-d tree, in single precision: ties
// closer than a micrometre at part scale may go either way), queried in parallel. Empty `points`
// give an empty answer.
std::vector<size_t> nearestPoints(const std::vector<Vec3>& points, const std::vector<Vec3>& queries);

}  // namespace spira
