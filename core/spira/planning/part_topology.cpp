#include "spira/planning/part_topology.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "spira/base/error.h"

namespace spira {
namespace {

double meanZ(const BoundaryLoop& loop, const TriangleMesh& mesh)
{
  double z = 0.0;
  for (int v : loop.vertices) z += mesh.vertices[static_cast<size_t>(v)].z();
  return loop.vertices.empty() ? 0.0 : z / static_cast<double>(loop.vertices.size());
}

void refuseDefects(const MeshReport& report)
{
  if (report.isPlannable()) return;
  std::ostringstream what;
  what << "the part mesh has defects that stop planning:";
  bool first = true;
  const bool noSurface = report.issueCount(MeshIssueKind::DegenerateFace) >= report.faceCount;
  for (const auto& issue : report.issues) {
    if ((issue.kind == MeshIssueKind::DegenerateFace && !noSurface) ||
        issue.kind == MeshIssueKind::DuplicateFace)
      continue;
    what << (first ? " " : ", ") << issue.count << " " << meshIssueName(issue.kind);
    if (!issue.positions.empty()) {
      const Vec3& p = issue.positions.front();
      what << " (first at " << p.x() << ", " << p.y() << ", " << p.z() << " mm)";
    }
    first = false;
  }
  throw InputError(what.str(),
                   "repair the mesh in the CAD or mesh tool (make it manifold with consistent normals)");
}

}  // namespace

PartTopology findPartTopology(const MeshReport& report, const TriangleMesh& mesh, double substrateZ,
                              int lowerOverride, bool allowBranches)
{
  // Several pieces first: an assembly's pieces touching one another read as defects of one mesh.
  if (report.componentCount > 1)
    throw InputError("the file holds " + std::to_string(report.componentCount) +
                         " separate pieces (an assembly, or a part with loose bits)",
                     "import one thin-walled part at a time: export that part alone from the CAD tool");
  refuseDefects(report);
  if (report.componentCount != 1)
    throw InputError("the part has no piece to plan", "import a part with a surface");
  const auto& loops = report.boundaryLoops;
  // One or two edges but no wall: every vertex is on its edge.
  if (report.hasNoWall())
    throw InputError("the part cannot be planned: " + report.classReason,
                     "import a thin wall that rises from its base edge (spira-cli info shows how it reads)");
  if (loops.empty())
    throw InputError("the part cannot be planned: " + report.classReason,
                     "give Spira the wall as a surface open at its base: its mid-surface, or its inner or "
                     "outer skin, exported without the base face (a thin-walled solid is planned on its "
                     "mid-surface unless --no-mid-surface)");
  if (loops.size() > 2 && !allowBranches)
    throw InputError("the part cannot be planned as one spiral: " + report.classReason,
                     "plan the whole part (each branch gets its own spiral), or cut it into walls with one "
                     "base edge and at most one top edge");
  PartTopology t;
  t.freeEdgeCount = loops.size();
  t.branched = loops.size() > 2;
  t.partClass =
      t.branched ? PartClass::Unsupported : (loops.size() == 2 ? PartClass::Open : PartClass::Closed);
  if (lowerOverride >= static_cast<int>(loops.size()))
    throw InputError("loop " + std::to_string(lowerOverride + 1) + " does not exist: the part has " +
                         std::to_string(loops.size()) + " boundary loop(s)",
                     "choose one of the loops 1 to " + std::to_string(loops.size()) +
                         " that 'spira-cli info' lists (--lower-loop N), or leave the choice automatic");
  if (lowerOverride >= 0) {
    t.lowerIndex = lowerOverride;
  } else {
    double lowest = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < loops.size(); ++i) {
      const double z = meanZ(loops[i], mesh);
      if (z < lowest) {
        lowest = z;
        t.lowerIndex = static_cast<int>(i);
      }
    }
  }
  t.lower = loops[static_cast<size_t>(t.lowerIndex)];
  double lowZ = std::numeric_limits<double>::infinity();
  for (int v : t.lower.vertices) lowZ = std::min(lowZ, mesh.vertices[static_cast<size_t>(v)].z());
  t.lowerGapToSubstrate = lowZ - substrateZ;
  if (t.partClass == PartClass::Open) {
    t.upperIndex = 1 - t.lowerIndex;
    t.upper = loops[static_cast<size_t>(t.upperIndex)];
  }
  return t;
}

void requireOnSubstrate(const PartTopology& topology, double substrateZ, double tolerance)
{
  const double gap = topology.lowerGapToSubstrate;
  if (!(std::abs(gap) > tolerance)) return;
  std::ostringstream what, hint;
  what << std::fixed << std::setprecision(2) << "the part does not stand on the substrate: its base (loop "
       << topology.lowerIndex + 1 << ", z " << topology.lower.zMin << " .. " << topology.lower.zMax
       << " mm) is " << std::abs(gap) << " mm " << (gap > 0.0 ? "above" : "below")
       << " the substrate plane z = " << substrateZ << " mm";
  hint << std::fixed << std::setprecision(2)
       << "drop the part onto the substrate (spira-cli plan --drop; Placement > Drop to Substrate in "
          "Spira), or plan on a substrate at z = "
       << substrateZ + gap << " mm (--substrate-z " << substrateZ + gap
       << "); if the base is the wrong loop, choose it with --lower-loop N";
  throw InputError(what.str(), hint.str());
}

void requireLevelBase(const PartTopology& topology, double substrateZ, double tolerance)
{
  const double rise = topology.lower.zMax - substrateZ;
  if (!(rise > tolerance)) return;
  std::ostringstream what, hint;
  what << std::fixed << std::setprecision(2) << "the part's base edge (loop " << topology.lowerIndex + 1
       << ") is not level: it runs from z " << topology.lower.zMin << " to " << topology.lower.zMax
       << " mm, up to " << rise << " mm above the substrate plane z = " << substrateZ
       << " mm, where the first revolution can bridge at most " << tolerance
       << " mm (half the thinnest bead): it would start in mid-air";
  hint << std::fixed << std::setprecision(2) << "cut the part level at z = " << topology.lower.zMax
       << " mm and stand it on the substrate (spira-cli plan --level-base or Placement > Level Base in Spira "
          "do both; the part loses "
       << topology.lower.zMax - topology.lower.zMin
       << " mm at its base), or give a part whose base edge lies in "
       << "one plane";
  throw BaseNotLevelError(what.str(), hint.str(), topology.lower);
}

}  // namespace spira
