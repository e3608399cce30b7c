#include "part_placement.h"

#include <cmath>

namespace spira::cli {
namespace {

int parseLoop(const std::string& text)
{
  constexpr long long kMaxLoop = 999999;
  return static_cast<int>(
             wholeNumberFlag("--lower-loop", text, 1, kMaxLoop,
                             "a loop number from 1, as 'spira-cli info' lists the loops, e.g. "
                             "--lower-loop 1, or leave it out to stand the part on its lowest loop")) -
         1;
}

double parseZ(const std::string& text)
{
  constexpr double kMaxZ = 1e6;
  const char* example = "a height in mm, e.g. --substrate-z 0";
  const double z = finiteNumberFlag("--substrate-z", text, example);
  if (std::abs(z) > kMaxZ)
    throw UsageError("--substrate-z: '" + text + "' is out of range (-1e6 to 1e6 mm)", example);
  return z;
}

}  // namespace

PartPlacement PartPlacement::take(Args& args)
{
  PartPlacement p;
  const std::string loop = args.takeOption("--lower-loop");
  const std::string z = args.takeOption("--substrate-z");
  p.drop = args.takeSwitch("--drop");
  p.levelBase = args.takeSwitch("--level-base");
  if (!loop.empty()) p.lowerLoop = parseLoop(loop);
  if (!z.empty()) p.substrateZ = parseZ(z);
  return p;
}

PlacementChange PartPlacement::apply(ImportedPart& part) const
{
  return placePart(part.mesh, part.report, PartPlacementOptions{lowerLoop, substrateZ, drop, levelBase});
}

}  // namespace spira::cli
