#include "spira/planning/substrate_contact.h"

#include <iomanip>
#include <limits>
#include <sstream>

#include "spira/base/error.h"
#include "spira/contour/surface_point.h"

namespace spira {
namespace {

struct Contact {
  double mean = 0.0, max = 0.0;
  Vec3 farthest = Vec3::Zero();
};

Contact contactOf(const TriangleMesh& part, const BoundaryLoop& loop, const TriangleMesh& substrate)
{
  Contact c;
  for (int v : loop.vertices) {
    const Vec3& p = part.vertices[size_t(v)];
    const double d = (closestSurfacePoint(substrate, p).position - p).norm();
    c.mean += d / double(loop.vertices.size());
    if (d > c.max) c.max = d, c.farthest = p;
  }
  return c;
}

}  // namespace

void standOnSubstrateMesh(PartTopology& topology, const MeshReport& report, const TriangleMesh& mesh,
                          const SubstrateSurface& substrate, int lowerOverride, double tolerance)
{
  const TriangleMesh& under = *substrate.surfaceMesh();
  const auto& loops = report.boundaryLoops;
  std::vector<Contact> contacts;
  for (const BoundaryLoop& loop : loops) contacts.push_back(contactOf(mesh, loop, under));
  int lower = lowerOverride;
  if (lower < 0) {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < loops.size(); ++i)
      if (contacts[i].mean < best) best = contacts[i].mean, lower = int(i);
  }
  topology.lowerIndex = lower;
  topology.lower = loops[size_t(lower)];
  topology.lowerGapToSubstrate = contacts[size_t(lower)].max;
  if (topology.partClass == PartClass::Open) {
    topology.upperIndex = 1 - lower;
    topology.upper = loops[size_t(topology.upperIndex)];
  }
  const Contact& c = contacts[size_t(lower)];
  if (!(c.max > tolerance)) return;
  std::ostringstream what;
  what << std::fixed << std::setprecision(2)
       << "the part does not stand on the substrate mesh: its base edge (loop " << lower + 1
       << ") lies up to " << c.max << " mm from the substrate's surface, at (" << c.farthest.x() << ", "
       << c.farthest.y() << ", " << c.farthest.z() << ") mm, where the first revolution can bridge at most "
       << tolerance << " mm (half the thinnest bead)";
  throw InputError(what.str(),
                   "place the part so that its base edge follows the substrate (model the feature on the "
                   "substrate it is built on, in the same coordinates), choose the base with --lower-loop N, "
                   "or plan on the plate (without --substrate)");
}

}  // namespace spira
