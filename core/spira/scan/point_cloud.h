#pragma once

#include <vector>

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// A measured point set: a laser-line scan of a substrate or of a part as it grows. Millimetres, in
// the frame of the file it came from until aligned (then the nominal part's frame).
struct PointCloud {
  std::vector<Vec3> points;
  std::vector<Vec3> normals;  // empty, or one unit normal per point
  bool hasNormals() const { return !normals.empty() && normals.size() == points.size(); }
  size_t size() const { return points.size(); }
  bool empty() const { return points.empty(); }
};

// The cloud moved by T (points and normals): T maps the cloud's frame into the new one.
PointCloud transformed(const PointCloud& cloud, const Transform& T);

BoundingBox boundsOf(const PointCloud& cloud);

}  // namespace spira
