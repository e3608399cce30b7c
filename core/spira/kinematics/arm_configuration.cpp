#include "spira/kinematics/arm_configuration.h"

#include "spira/base/error.h"

namespace spira {

ArmConfiguration ArmConfiguration::fromIndex(int index)
{
  if (index < 0 || index > 7) throw InternalError("arm configuration index out of 0..7");
  ArmConfiguration c;
  c.front = (index & 1) == 0;
  c.up = (index & 2) == 0;
  c.noFlip = (index & 4) == 0;
  return c;
}

std::array<ArmConfiguration, 8> ArmConfiguration::all()
{
  std::array<ArmConfiguration, 8> out;
  for (int i = 0; i < 8; ++i) out[static_cast<size_t>(i)] = fromIndex(i);
  return out;
}

std::string ArmConfiguration::label() const
{
  return std::string(front ? "front" : "back") + "/" + (up ? "up" : "down") + "/" +
         (noFlip ? "noflip" : "flip");
}

ArmConfiguration ArmConfiguration::parse(const std::string& label)
{
  for (const ArmConfiguration& c : all())
    if (c.label() == label) return c;
  throw InputError("'" + label + "' is not an arm configuration",
                   "write shoulder/elbow/wrist as front|back / up|down / noflip|flip, e.g. front/up/noflip");
}

}  // namespace spira
