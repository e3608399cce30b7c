#pragma once

#include <memory>

#include "spira/base/transform.h"
#include "spira/document/substrate.h"
#include "spira/mesh/substrate_surface.h"

namespace spira {

// A document's substrate mesh in the frame a part placed at T_world_part is planned in (the world's axes,
// the part's origin); nullptr for a plane, which plans keep as a height (PlanRequest::substrateZ).
std::shared_ptr<const SubstrateSurface> substrateInBuildFrame(const Substrate& substrate,
                                                              const Transform& T_world_part);

}  // namespace spira
