#include "spira/planning/part_placement.h"

#include <iomanip>
#include <sstream>

#include "spira/planning/level_base.h"
#include "spira/planning/part_topology.h"

namespace spira {

PlacementChange placePart(TriangleMesh& mesh, MeshReport& report, const PartPlacementOptions& options)
{
  PlacementChange change;
  if (options.levelBase) {
    const PartTopology topology = findPartTopology(report, mesh, options.substrateZ, options.lowerLoop, true);
    LevelledBase levelled = levelBase(mesh, topology.lower);
    change.levelled = true;
    change.cutZ = levelled.cutZ;
    change.removed = levelled.removed;
    mesh = std::move(levelled.mesh);
    report = validateMesh(mesh);
  }
  if (!(options.drop || options.levelBase) || report.bounds.empty()) return change;
  const double shift = options.substrateZ - report.bounds.min.z();
  if (shift == 0.0) return change;
  for (Vec3& v : mesh.vertices) v.z() += shift;
  report = validateMesh(mesh);
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

}  // namespace spira
