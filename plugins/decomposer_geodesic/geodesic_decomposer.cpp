#include "geodesic_decomposer.h"

#include <memory>

#include "geodesic_decomposition.h"
#include "spira/base/error.h"
#include "spira/plugin/decomposer_params.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(pointsPerRevolutionParam(
      "The base is cut at this many constant angles and each cut starts one geodesic; fill-in "
      "generatrices may add more where geodesics leave gaps."));
  defs.push_back(levelSpacingParam("Every generatrix gets the same number of points."));
  defs.push_back(numberParam(
      "coverage_tolerance", 0.2, 0.001, 100.0, "mm",
      {"Coverage tolerance",
       "Largest gap allowed between the surface and the strip joining two neighbouring generatrices (thesis "
       "eps_0, Eq. 3.9); beyond it a fill-in generatrix is inserted between them.",
       "Coverage"}));
  defs.push_back(integerParam(
      "fill_rounds", 6, 0, 12,
      {"Fill-in rounds",
       "How many times the coverage check may insert fill-in generatrices between neighbours (each round "
       "halves the gaps it splits); 0 turns the fill-in off.",
       "Coverage"}));
  return ParamSchema(std::move(defs));
}

}  // namespace

GeodesicDecomposer::GeodesicDecomposer() : schema_(makeSchema()) {}

std::string GeodesicDecomposer::description() const
{
  return "Generatrices along exact geodesics from constant-angle base points to the nearest point of the "
         "upper edge (open parts) or to the closure point (closed parts), with fill-in generatrices where "
         "they leave gaps. Slower than iso-values.";
}

bool GeodesicDecomposer::accepts(const DecomposeInput& input, std::string* why) const
{
  return hasPlannableEdges(input, why);
}

DecomposeResult GeodesicDecomposer::decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                                     Progress& progress) const
{
  geodesic::GeodesicOptions options;
  options.pointsPerRevolution = static_cast<size_t>(values.getInt("points_per_rev"));
  options.pointSpacing = values.internal(schema_, "level_spacing");
  options.coverageTolerance = values.internal(schema_, "coverage_tolerance");
  options.fillRounds = static_cast<int>(values.getInt("fill_rounds"));
  options.window = {input.window.hMin, input.window.hMax, input.window.tolerance};
  options.beadWidth = input.window.beadWidth;
  const bool open = input.partClass == PartClass::Open;
  // The planner's field on closed parts is the distance from the base: the fallback closure point.
  const std::vector<double>* baseDistance = open ? nullptr : input.field;
  geodesic::GeodesicDecomposition d = geodesic::decomposeByGeodesics(
      input.mesh, input.lower, open ? &*input.upper : nullptr, open ? std::nullopt : input.closurePoint,
      baseDistance, options, progress);
  DecomposeResult out;
  out.generatrices = std::move(d.generatrices);
  out.warnings = std::move(d.warnings);
  return out;
}

}  // namespace spira

void spira_register_decomposer_geodesic(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::GeodesicDecomposer>());
}
