#include "spira/planning/part_topology.h"

#include <cmath>
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
  for (const auto& issue : report.issues) {
    if (issue.kind == MeshIssueKind::DegenerateFace || issue.kind == MeshIssueKind::DuplicateFace) continue;
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
  refuseDefects(report);
  if (report.componentCount != 1)
    throw InputError("the part has " + std::to_string(report.componentCount) + " separate pieces",
                     "import one thin-walled part at a time");
  const auto& loops = report.boundaryLoops;
  if (loops.empty() || (loops.size() > 2 && !allowBranches))
    throw InputError(
        "the part cannot be planned: " + report.classReason,
        "Spira plans walls with one free edge on the substrate (closed parts) or two (open parts); "
        "fill holes in the mesh tool");
  PartTopology t;
  t.freeEdgeCount = loops.size();
  t.branched = loops.size() > 2;
  t.partClass =
      t.branched ? PartClass::Unsupported : (loops.size() == 2 ? PartClass::Open : PartClass::Closed);
  if (lowerOverride >= static_cast<int>(loops.size()))
    throw InputError("lower boundary " + std::to_string(lowerOverride) + " does not exist (the part has " +
                         std::to_string(loops.size()) + ")",
                     "choose a loop index from 'spira-cli info', counted from 0, or -1 for automatic");
  if (lowerOverride >= 0) {
    t.lowerIndex = lowerOverride;
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < loops.size(); ++i) {
      const double gap = std::abs(meanZ(loops[i], mesh) - substrateZ);
      if (gap < best) {
        best = gap;
        t.lowerIndex = static_cast<int>(i);
      }
    }
  }
  t.lower = loops[static_cast<size_t>(t.lowerIndex)];
  t.lowerGapToSubstrate = std::abs(meanZ(t.lower, mesh) - substrateZ);
  if (t.partClass == PartClass::Open) {
    t.upperIndex = 1 - t.lowerIndex;
    t.upper = loops[static_cast<size_t>(t.upperIndex)];
  }
  return t;
}

}  // namespace spira
