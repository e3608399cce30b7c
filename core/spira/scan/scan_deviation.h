#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/scan/point_cloud.h"

namespace spira {

// The closest point of a mesh to any point, and its signed distance: positive outside (along the
// surface's outward normal, interpolated from the vertex normals at the closest point). CGAL's AABB
// tree, built once.
class MeshDistance {
 public:
  explicit MeshDistance(const TriangleMesh& mesh);
  ~MeshDistance();
  MeshDistance(const MeshDistance&) = delete;
  MeshDistance& operator=(const MeshDistance&) = delete;

  struct Hit {
    Vec3 point = Vec3::Zero();
    size_t face = 0;
    double signedDistance = 0.0;
  };
  Hit closest(const Vec3& p) const;

 private:
  struct Tree;
  std::unique_ptr<Tree> tree_;
  const TriangleMesh& mesh_;
  std::vector<Vec3> normals_;
};

struct DeviationStats {
  size_t count = 0;
  double mean = 0.0, rms = 0.0;  // of the signed distances, mm
  double p95 = 0.0;              // 95th percentile of their magnitude, mm
  double min = 0.0, max = 0.0;   // signed, mm
  double binMin = 0.0, binWidth = 0.0;
  std::vector<size_t> histogram;  // counts per bin from binMin
};

DeviationStats deviationStats(const std::vector<double>& distances, int bins = 40);

// Signed distance of every scan point to the part (mm, positive outside), in parallel.
std::vector<double> scanDeviation(const PointCloud& scan, const TriangleMesh& part, Progress& progress);

// A scan much larger or smaller than the part was most likely written in other units: names the
// likely unit and the factor, or nothing when the sizes agree within a factor of 3.
std::optional<std::string> scanUnitHint(const BoundingBox& scan, const BoundingBox& part);

}  // namespace spira
