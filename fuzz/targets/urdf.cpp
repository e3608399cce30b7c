// A robot description (URDF) read into the kinematic chain from base_link to tool0, the link
// names of the bundled robots.
#include "../fuzz_support.h"
#include "spira/kinematics/kinematic_chain.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  return spira::fuzz::refusalsAllowed([&] {
    spira::KinematicChain::fromUrdfString(std::string(spira::fuzz::bytes(data, size)), "base_link", "tool0");
  });
}
