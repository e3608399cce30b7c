#pragma once

namespace spira {

// What a torch check found, as bits so that one check can report several.
enum CollisionKind : unsigned {
  kCollisionNone = 0,
  kCollisionDeposit = 1u << 0,    // material laid earlier on the plan
  kCollisionSubstrate = 1u << 1,  // the substrate plane or mesh
  kCollisionObstacle = 1u << 2,   // a positioner, table, clamp... mesh
};

}  // namespace spira
