#include "spira/plugin/decomposer_params.h"

namespace spira {

ParamDef pointsPerRevolutionParam(const std::string& how)
{
  return integerParam("points_per_rev", 360, 8, 20000,
                      {"Points per revolution",
                       "Number of generatrices, i.e. path points per revolution. " + how, "Discretisation"});
}

ParamDef levelSpacingParam(const std::string& how)
{
  return numberParam("level_spacing", 0.0, 0.0, 1000.0, "mm",
                     {"Point spacing",
                      "Mean distance on the surface between consecutive points of each generatrix. " + how +
                          " 0 uses the mesh's mean edge length, the finest spacing the mesh resolves.",
                      "Discretisation"});
}

bool hasPlannableEdges(const DecomposeInput& input, std::string* why)
{
  auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (input.partClass == PartClass::Unsupported)
    return no("the part is neither open (two free edges) nor closed (one free edge)");
  if (input.partClass == PartClass::Open && !input.upper) return no("the open part has no upper edge");
  if (input.lower.vertices.size() < 3) return no("the part has no lower edge");
  if (input.field && input.field->size() != input.mesh.vertexCount())
    return no("the scalar field has " + std::to_string(input.field->size()) + " values for " +
              std::to_string(input.mesh.vertexCount()) + " vertices");
  return true;
}

}  // namespace spira
