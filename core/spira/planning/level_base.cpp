#include "spira/planning/level_base.h"

#include <iomanip>
#include <sstream>

#include "spira/base/error.h"
#include "spira/contour/mesh_split.h"
#include "spira/mesh/mesh_report.h"

namespace spira {

LevelledBase levelBase(const TriangleMesh& mesh, const BoundaryLoop& lower)
{
  LevelledBase out;
  out.cutZ = lower.zMax;
  out.removed = lower.zMax - lower.zMin;
  std::vector<double> height(mesh.vertices.size());
  for (size_t v = 0; v < mesh.vertices.size(); ++v) height[v] = mesh.vertices[v].z();
  const LevelCut cut = cutAlongLevel(mesh, height, out.cutZ);
  std::vector<int> kept;
  std::vector<std::uint8_t> mask(cut.mesh.faces.size(), 0);
  for (size_t f = 0; f < cut.mesh.faces.size(); ++f)
    if (cut.above[f]) {
      kept.push_back(static_cast<int>(f));
      mask[f] = 1;
    }
  std::vector<int> component;
  const int pieces = kept.empty() ? 0 : faceComponents(cut.mesh, mask, component);
  if (pieces != 1) {
    std::ostringstream what;
    what << std::fixed << std::setprecision(2) << "levelling the base at z = " << out.cutZ << " mm leaves "
         << pieces << " pieces of the part: its wall dips below that plane away from the base";
    throw InputError(what.str(), "cut the part level in a mesh tool where its wall is whole, and plan that");
  }
  out.mesh = extractFaces(cut.mesh, kept).mesh;
  // The new base edge runs through corners the cut counted as on the plane (within a twentieth of
  // an edge's rise, so that it made no slivers) and vertices interpolated on it: all go onto it.
  const MeshReport report = validateMesh(out.mesh);
  if (!report.boundaryLoops.empty())
    for (int v : report.boundaryLoops.front().vertices)
      out.mesh.vertices[static_cast<size_t>(v)].z() = out.cutZ;
  return out;
}

}  // namespace spira
