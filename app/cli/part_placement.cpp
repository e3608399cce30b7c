#include "part_placement.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "spira/mesh/mesh_report.h"
#include "spira/planning/level_base.h"
#include "spira/planning/part_topology.h"

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
  PlacementChange change;
  if (levelBase) {
    const PartTopology topology = findPartTopology(part.report, part.mesh, substrateZ, lowerLoop, true);
    LevelledBase levelled = spira::levelBase(part.mesh, topology.lower);
    change.levelled = true;
    change.cutZ = levelled.cutZ;
    change.removed = levelled.removed;
    part.mesh = std::move(levelled.mesh);
    part.report = validateMesh(part.mesh);
  }
  if (!(drop || levelBase) || part.report.bounds.empty()) return change;
  const double shift = substrateZ - part.report.bounds.min.z();
  if (shift == 0.0) return change;
  for (Vec3& v : part.mesh.vertices) v.z() += shift;
  part.report = validateMesh(part.mesh);
  change.dropped = shift;
  return change;
}

std::string PlacementChange::text(double substrateZ) const
{
  std::ostringstream o;
  o << std::fixed << std::setprecision(3);
  if (levelled)
    o << "levelled the base: cut the part at z = " << cutZ << " mm, " << removed << " mm off its base\n";
  if (dropped != 0.0)
    o << "dropped the part " << dropped << " mm along z onto the substrate (z = " << substrateZ << " mm)\n";
  return o.str();
}

}  // namespace spira::cli
