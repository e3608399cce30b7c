#include "max_min_geodesic.h"

#include <cmath>

#include "closure_refinement.h"
#include "spira/base/error.h"
#include "spira/field/field_ops.h"
#include "spira/field/heat_distance.h"

namespace spira::closure_zone {

MaxMinGeodesicClosure::MaxMinGeodesicClosure()
    : schema_({
          {"heat_time_scale",
           ParamType::Double,
           1.0,
           0.1,
           100.0,
           "",
           "Heat time scale",
           "Heat-method time step as a multiple of the squared mean edge length (1 = the thesis's t = h^2). "
           "Larger values smooth the distance on noisy meshes.",
           "Closure point",
           {}},
          {"refine",
           ParamType::Bool,
           true,
           {},
           {},
           "",
           "Refine below mesh vertices",
           "Fit a quadratic to the distance around the best vertex and place the closure point at its "
           "maximum, "
           "inside a triangle, instead of on a mesh vertex.",
           "Closure point",
           {}},
      })
{
}

std::string MaxMinGeodesicClosure::description() const
{
  return "Closure point of a closed part: the surface point farthest (geodesically) from the whole base "
         "edge, "
         "from one multi-source heat-method distance field, refined inside triangles.";
}

ClosureResult MaxMinGeodesicClosure::find(const ClosureInput& input, const ParamSet& params,
                                          Progress& progress) const
{
  const TriangleMesh& mesh = input.mesh;
  if (input.baseVertices.empty())
    throw InputError("the closure search needs the base edge, and it is empty",
                     "check that the part has an open base edge on the substrate");
  const ParamSet p = params.withDefaults(schema_);
  schema_.validate(p);
  if (input.baseDistance && input.baseDistance->size() != mesh.vertexCount())
    throw InternalError("closure search given a distance field of the wrong size");
  std::vector<double> computed;
  if (!input.baseDistance) {
    HeatDistanceOptions options;
    options.timeScale = p.getDouble("heat_time_scale");
    SubProgress fieldProgress(progress, 0.0, 0.9, "geodesic distance from the base");
    computed = heatGeodesicDistance(mesh, input.baseVertices, options, fieldProgress);
  }
  const std::vector<double>& distance = input.baseDistance ? *input.baseDistance : computed;
  progress.checkCancel();
  const int peak = argmaxVertex(distance);
  if (peak < 0)
    throw AlgorithmError("no finite geodesic distance from the base was found",
                         "the part may be disconnected from its base edge: check it with 'spira-cli info'");
  ClosureResult r =
      p.getBool("refine") ? refineMaximum(mesh, distance, peak) : atVertex(mesh, distance, peak);
  progress.report(1.0, "closure point");
  return r;
}

}  // namespace spira::closure_zone
