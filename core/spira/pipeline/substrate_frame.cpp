#include "spira/pipeline/substrate_frame.h"

namespace spira {

std::shared_ptr<const SubstrateSurface> substrateInBuildFrame(const Substrate& substrate,
                                                              const Transform& T_world_part)
{
  if (substrate.kind != Substrate::Kind::Mesh || !substrate.mesh) return nullptr;
  TriangleMesh mesh = *substrate.mesh;
  for (Vec3& v : mesh.vertices) v -= T_world_part.translation();
  return std::make_shared<const SubstrateSurface>(SubstrateSurface::mesh(std::move(mesh)));
}

}  // namespace spira
