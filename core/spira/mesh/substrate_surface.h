#pragma once

#include <memory>

#include "spira/base/transform.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

class RayBvh;

// What the part is built on, in the part's build frame: the plane z = planeZ (the usual plate), or a
// surface mesh (a pipe, a curved plate, a previous part) that the part's base edge follows.
class SubstrateSurface {
 public:
  static SubstrateSurface plane(double z);
  // Throws InputError for a mesh without faces.
  static SubstrateSurface mesh(TriangleMesh mesh);

  bool isPlane() const { return !mesh_; }
  double planeZ() const { return planeZ_; }
  const TriangleMesh* surfaceMesh() const;  // nullptr for the plane

  // How far below p, along -up (unit), the substrate lies: for the plane (p.z - z) / up.z where up.z
  // is at least 0.1 (a flatter column does not look down onto it), for a mesh the first face the column
  // meets, looking from `above` over p down to `below` under it. Negative when p lies under the
  // substrate; infinity when the column misses it.
  double depthBelow(const Vec3& p, const Vec3& up, double above, double below) const;

 private:
  struct Mesh;
  double planeZ_ = 0.0;
  std::shared_ptr<const Mesh> mesh_;
};

}  // namespace spira
