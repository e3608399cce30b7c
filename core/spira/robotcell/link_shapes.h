#pragma once

#include <memory>
#include <string>
#include <vector>

#include "spira/collision/triangle_bvh.h"
#include "spira/kinematics/kinematic_chain.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The collision geometry of a robot's links (URDF <collision>: meshes, boxes, cylinders, spheres),
// in mm, each with the chain that places its link: T_base_link(q) = chain.forward(q.head(joints)),
// where q are the joints of the whole arm (the link moves with the first `joints` of them).
struct LinkShape {
  std::string link;
  std::unique_ptr<KinematicChain> chain;  // base link -> this link
  size_t joints = 0;
  TriangleMesh mesh;  // in the link frame
  std::unique_ptr<TriangleBvh> bvh;
  bool standInCube = false;  // its mesh file was missing: a 100 mm cube stands in
  // What the link looks like (URDF <visual>, origins applied), in the link frame; when the visual
  // geometry is absent or unreadable, a copy of `mesh` (then displayIsVisual is false).
  TriangleMesh display;
  bool displayIsVisual = false;
};

struct RobotShapes {
  std::vector<LinkShape> links;
  std::vector<std::string> warnings;  // missing or unreadable meshes, by file
};

// Reads the collision and visual geometry of every link of the URDF from `baseLink` along the chain
// to `tipLink` (and the links fixed to them). Mesh paths are relative to the URDF's folder; meshes
// are read by readLinkMesh (STL, COLLADA, OBJ, ...). A missing or unreadable collision mesh gets a
// 100 mm stand-in cube and a warning, an unreadable visual mesh falls back to the collision geometry
// with a warning, never an error: the cell still displays and plans. Throws InputError when the
// URDF does not parse.
RobotShapes readRobotShapes(const std::string& urdfPath, const std::string& baseLink,
                            const std::string& tipLink);

}  // namespace spira
