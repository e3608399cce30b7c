#include "spira/robotcell/robot_collision_model.h"

#include "spira/collision/mesh_intersection.h"

namespace spira {
namespace {

TriangleMesh plateMesh(const Vec3& size)
{
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                            (i & 4 ? 0.0 : -1.0) * size.z());
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
                           {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.faces.push_back({q[0], q[1], q[2]});
    m.faces.push_back({q[0], q[2], q[3]});
  }
  return m;
}

Eigen::VectorXd head(const Eigen::VectorXd& q, size_t n)
{
  return q.head(static_cast<Eigen::Index>(n));
}

}  // namespace

RobotCollisionModel::RobotCollisionModel(const RobotCell& cell, const TriangleMesh& part,
                                         const Vec3& plateSize, double plateTopZ)
    : cell_(cell),
      arm_(readRobotShapes(cell.record().robotUrdf, cell.record().robotBaseLink, cell.record().robotTipLink)),
      part_(part),
      plate_(plateMesh(plateSize))
{
  partPlate_.translation() = Vec3(0, 0, plateTopZ);
  warnings_ = arm_.warnings;
  if (cell.positioner()) {
    positioner_ = readRobotShapes(cell.record().positionerUrdf, cell.record().positionerBaseLink,
                                  cell.record().positionerTipLink);
    warnings_.insert(warnings_.end(), positioner_.warnings.begin(), positioner_.warnings.end());
  }
}

std::vector<std::string> RobotCollisionModel::armHits(const JointVector& q, const Transform& basePart,
                                                      const Eigen::Vector2d& e, double margin) const
{
  std::vector<std::string> hits;
  const Eigen::VectorXd qx = q;
  const Eigen::VectorXd ex = e;
  for (const LinkShape& link : arm_.links) {
    // The first links hardly move near the part; all are checked alike, cheap when far apart.
    const Transform baseLink = link.chain->forward(head(qx, link.joints));
    bool hit = meshesIntersect(*link.bvh, baseLink, part_, basePart, margin) ||
               meshesIntersect(*link.bvh, baseLink, plate_, basePart * partPlate_, margin);
    for (size_t k = 0; !hit && cell_.positioner() && k < positioner_.links.size(); ++k) {
      const LinkShape& p = positioner_.links[k];
      const Transform basePosLink = cell_.basePositioner() * p.chain->forward(head(ex, p.joints));
      hit = meshesIntersect(*link.bvh, baseLink, *p.bvh, basePosLink, margin);
    }
    if (hit) hits.push_back(link.link);
  }
  return hits;
}

}  // namespace spira
