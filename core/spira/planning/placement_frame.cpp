#include "spira/planning/placement_frame.h"

#include <algorithm>

namespace spira {

PlacementFrame::PlacementFrame(const Transform& T_world_part)
    : R_(T_world_part.linear()), identity_(T_world_part.linear().isIdentity(1e-14))
{
}

TriangleMesh PlacementFrame::toBuild(const TriangleMesh& partMesh) const
{
  Transform T = Transform::Identity();
  T.linear() = R_;
  return partMesh.transformed(T);
}

namespace {

void rotate(Trajectory& trajectory, const Mat3& R)
{
  for (TrajectoryPoint& p : trajectory.points) {
    p.position = R * p.position;
    p.normal = R * p.normal;
    p.tangent = R * p.tangent;
    p.build = R * p.build;
  }
}

}  // namespace

void PlacementFrame::toBuild(Trajectory& trajectory) const
{
  rotate(trajectory, R_);
}

void PlacementFrame::toPart(Trajectory& trajectory) const
{
  rotate(trajectory, R_.transpose());
}

void PlacementFrame::toPart(Generatrices& generatrices) const
{
  const Mat3 Rt = R_.transpose();
  for (Polyline& line : generatrices.lines)
    for (Vec3& q : line) q = Rt * q;
  for (auto& normals : generatrices.normals)
    for (Vec3& n : normals) n = Rt * n;
  generatrices.closurePoint = Rt * generatrices.closurePoint;
  for (Vec3& q : generatrices.guide) q = Rt * q;
}

namespace {

std::vector<int> sortedVertices(const BoundaryLoop& loop)
{
  std::vector<int> v = loop.vertices;
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

int PlacementFrame::loopIndexInBuild(const std::vector<BoundaryLoop>& partLoops,
                                     const std::vector<BoundaryLoop>& buildLoops, int partIndex)
{
  if (partIndex < 0 || static_cast<size_t>(partIndex) >= partLoops.size()) return -1;
  const std::vector<int> wanted = sortedVertices(partLoops[static_cast<size_t>(partIndex)]);
  for (size_t k = 0; k < buildLoops.size(); ++k)
    if (sortedVertices(buildLoops[k]) == wanted) return static_cast<int>(k);
  return -1;
}

}  // namespace spira
