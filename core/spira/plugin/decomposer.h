#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"
#include "spira/plugin/plugin.h"

namespace spira {

// The part as a decomposer sees it: the welded mesh and its free edges.
struct DecomposeInput {
  const TriangleMesh& mesh;
  PartClass partClass = PartClass::Unsupported;
  BoundaryLoop lower;                 // on the substrate
  std::optional<BoundaryLoop> upper;  // open parts only
  std::optional<Vec3> closurePoint;   // closed parts: from a closure finder, if already known
  // Per-vertex scalar field computed upstream (one value per mesh vertex), or nullptr. Closed
  // parts: geodesic distance from the lower edge; open parts: the harmonic field, 0 on the lower
  // edge and 1 on the upper one. Field-based decomposers (decomposer.isovalue) need it; the
  // caller keeps it alive for the duration of the call.
  const std::vector<double>* field = nullptr;
};

struct DecomposeResult {
  Generatrices generatrices;
  std::vector<std::string> warnings;
};

class DecomposerPlugin : public Plugin {
 public:
  PluginKind kind() const override { return PluginKind::Decomposer; }
  // Whether this strategy can handle the part; when not, `why` says why in plain words.
  virtual bool accepts(const DecomposeInput& input, std::string* why) const = 0;
  virtual DecomposeResult decompose(const DecomposeInput& input, const ParamSet& params,
                                    Progress& progress) const = 0;
};

}  // namespace spira
