#include "spira/scan/point_cloud.h"

namespace spira {

PointCloud transformed(const PointCloud& cloud, const Transform& T)
{
  PointCloud out;
  out.points.reserve(cloud.size());
  for (const Vec3& p : cloud.points) out.points.push_back(T * p);
  out.normals.reserve(cloud.normals.size());
  for (const Vec3& n : cloud.normals) out.normals.push_back(T.linear() * n);
  return out;
}

BoundingBox boundsOf(const PointCloud& cloud)
{
  return finiteBounds(cloud.points.data(), cloud.points.size());
}

}  // namespace spira
