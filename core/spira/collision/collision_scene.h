#pragma once

#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "spira/collision/convex_shape.h"
#include "spira/collision/triangle_bvh.h"

namespace spira {

// The fixed surroundings of a plan, in the part frame: the substrate (a plane or a mesh) and any
// obstacle meshes (positioner, table, clamps). Meshes are placed once, by T_part_mesh, when added;
// a scene is a cheap value to copy (hierarchies are shared).
class CollisionScene {
 public:
  // The substrate as a plane through `point`; the solid lies on the -normal side.
  void setSubstratePlane(const Vec3& point, const Vec3& normal);
  void setSubstrateMesh(const TriangleMesh& mesh, const Transform& T_part_mesh = Transform::Identity());
  void addObstacle(std::string name, const TriangleMesh& mesh,
                   const Transform& T_part_mesh = Transform::Identity());

  bool hasSubstratePlane() const { return hasPlane_; }
  size_t obstacleCount() const { return obstacles_.size(); }
  const std::string& obstacleName(size_t k) const { return obstacles_[k].name; }

  // CollisionKind bits of what lies within `margin` mm of the shape (part frame). Cheapest first.
  unsigned hits(const ConvexShape& shape, double margin) const;
  // The first obstacle index within `margin`, or -1 (to name it in a report).
  int obstacleHit(const ConvexShape& shape, double margin) const;
  // Distance from the shape to the nearest surrounding solid, 0 when touching or below the
  // substrate plane, capped at maxDistance; within `slack` mm above the exact value (see TriangleBvh).
  double clearance(const ConvexShape& shape, double maxDistance = std::numeric_limits<double>::infinity(),
                   double slack = 0.0) const;

 private:
  struct Obstacle {
    std::string name;
    std::shared_ptr<const TriangleBvh> bvh;
  };
  bool hasPlane_ = false;
  Vec3 planePoint_ = Vec3::Zero();
  Vec3 planeNormal_ = Vec3::UnitZ();
  std::shared_ptr<const TriangleBvh> substrate_;
  std::vector<Obstacle> obstacles_;
};

}  // namespace spira
