#pragma once

#include "spira/base/transform.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

// The planner builds along +z with the substrate below. A part placed with a tilt (rotated about a
// horizontal axis) must therefore be planned with the world's "up", not its own frame's: the
// mesh is turned into the build frame (the part frame rotated like the world sees it, no
// translation), planned there, and the results turned back so they stay in the part frame the
// document stores them in.
class PlacementFrame {
 public:
  explicit PlacementFrame(const Transform& T_world_part);

  // Whether the build frame is the part frame (no tilt and no turn): nothing to convert.
  bool identity() const { return identity_; }
  const Mat3& rotation() const { return R_; }

  TriangleMesh toBuild(const TriangleMesh& partMesh) const;
  Vec3 pointToPart(const Vec3& build) const { return R_.transpose() * build; }
  void toBuild(Trajectory& trajectory) const;
  void toPart(Trajectory& trajectory) const;
  void toPart(Generatrices& generatrices) const;

  // Boundary loops are listed by height, so a tilt reorders them: the index of the loop of
  // `partLoops[partIndex]` among `buildLoops` (same vertex set), or -1 for -1 or no match.
  static int loopIndexInBuild(const std::vector<BoundaryLoop>& partLoops,
                              const std::vector<BoundaryLoop>& buildLoops, int partIndex);

 private:
  Mat3 R_;
  bool identity_;
};

}  // namespace spira
