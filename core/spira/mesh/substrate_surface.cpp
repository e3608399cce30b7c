#include "spira/mesh/substrate_surface.h"

#include <limits>

#include "spira/base/error.h"
#include "spira/mesh/ray_bvh.h"

namespace spira {

struct SubstrateSurface::Mesh {
  explicit Mesh(TriangleMesh m) : mesh(std::move(m)), tree(mesh) {}
  TriangleMesh mesh;
  RayBvh tree;
};

SubstrateSurface SubstrateSurface::plane(double z)
{
  SubstrateSurface s;
  s.planeZ_ = z;
  return s;
}

SubstrateSurface SubstrateSurface::mesh(TriangleMesh mesh)
{
  if (mesh.faces.empty())
    throw InputError("the substrate mesh has no faces", "give the surface the part is built on");
  SubstrateSurface s;
  s.mesh_ = std::make_shared<const Mesh>(std::move(mesh));
  return s;
}

const TriangleMesh* SubstrateSurface::surfaceMesh() const
{
  return mesh_ ? &mesh_->mesh : nullptr;
}

double SubstrateSurface::depthBelow(const Vec3& p, const Vec3& up, double above, double below) const
{
  constexpr double kInf = std::numeric_limits<double>::infinity();
  constexpr double kMinUpZ = 0.1;
  if (!mesh_) return up.z() >= kMinUpZ ? (p.z() - planeZ_) / up.z() : kInf;
  const RayHit hit = mesh_->tree.firstHit(p + above * up, -up, 0.0, above + below);
  return hit.face < 0 ? kInf : hit.distance - above;
}

}  // namespace spira
