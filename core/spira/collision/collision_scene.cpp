#include "spira/collision/collision_scene.h"

#include <algorithm>
#include <cmath>

#include "spira/base/error.h"
#include "spira/collision/collision_kind.h"

namespace spira {

void CollisionScene::setSubstratePlane(const Vec3& point, const Vec3& normal)
{
  if (!point.allFinite() || !normal.allFinite() || normal.norm() < 1e-12)
    throw InputError("the substrate plane needs a finite point and a non-zero normal",
                     "check the substrate placement");
  hasPlane_ = true;
  planePoint_ = point;
  planeNormal_ = normal.normalized();
}

void CollisionScene::setSubstrateMesh(const TriangleMesh& mesh, const Transform& T_part_mesh)
{
  substrate_ = std::make_shared<const TriangleBvh>(mesh.transformed(T_part_mesh));
}

void CollisionScene::addObstacle(std::string name, const TriangleMesh& mesh, const Transform& T_part_mesh)
{
  obstacles_.push_back({std::move(name), std::make_shared<const TriangleBvh>(mesh.transformed(T_part_mesh))});
}

unsigned CollisionScene::hits(const ConvexShape& shape, double margin) const
{
  unsigned found = 0;
  if (hasPlane_ && planeNormal_.dot(shape.support(-planeNormal_) - planePoint_) <= margin)
    found |= kCollisionSubstrate;
  if (!(found & kCollisionSubstrate) && substrate_ && substrate_->intersects(shape, margin))
    found |= kCollisionSubstrate;
  if (obstacleHit(shape, margin) >= 0) found |= kCollisionObstacle;
  return found;
}

int CollisionScene::obstacleHit(const ConvexShape& shape, double margin) const
{
  for (size_t k = 0; k < obstacles_.size(); ++k)
    if (obstacles_[k].bvh->intersects(shape, margin)) return static_cast<int>(k);
  return -1;
}

double CollisionScene::clearance(const ConvexShape& shape, double maxDistance, double slack) const
{
  double best = maxDistance;
  if (hasPlane_)
    best = std::min(best, std::max(0.0, planeNormal_.dot(shape.support(-planeNormal_) - planePoint_)));
  if (substrate_) best = std::min(best, substrate_->nearest(shape, best, slack).distance);
  for (const auto& o : obstacles_) best = std::min(best, o.bvh->nearest(shape, best, slack).distance);
  return best;
}

}  // namespace spira
