#pragma once

#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/plugin/plugin.h"

namespace spira {

struct ClosureResult {
  Vec3 point = Vec3::Zero();        // on the surface, not limited to vertices
  int face = -1;                    // face containing the point
  Vec3 barycentric = Vec3::Zero();  // of `point` in `face`
  double distance = 0.0;            // smallest geodesic distance from the point to the base, mm
  std::vector<std::string> warnings;
};

// What a closure search starts from.
struct ClosureInput {
  const TriangleMesh& mesh;
  std::vector<int> baseVertices;  // the vertices of the lower boundary (all of them: one source set)
  // The geodesic distance from the base at every vertex, when the caller already has it (the
  // planner computes it once for the decomposer too); nullptr lets the finder compute it.
  const std::vector<double>* baseDistance = nullptr;
};

class ClosureFinderPlugin : public Plugin {
 public:
  PluginKind kind() const override { return PluginKind::ClosureFinder; }
  virtual ClosureResult find(const ClosureInput& input, const ParamSet& params, Progress& progress) const = 0;
};

}  // namespace spira
