#include "isovalue_decomposer.h"

#include <memory>

#include "spira/base/error.h"
#include "spira/contour/isovalue_decomposition.h"
#include "spira/field/harmonic_field.h"
#include "spira/field/heat_distance.h"
#include "spira/plugin/decomposer_params.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(pointsPerRevolutionParam(
      "Every iso-contour is resampled to this many points; raise it for large or strongly curved parts."));
  defs.push_back(levelSpacingParam("Here: the spacing of the iso-contours."));
  return ParamSchema(std::move(defs));
}

}  // namespace

IsovalueDecomposer::IsovalueDecomposer() : schema_(makeSchema()) {}

std::string IsovalueDecomposer::description() const
{
  return "Generatrices along the iso-contours of a scalar field: geodesic distance from the base (closed "
         "parts, ending at the closure point) or harmonic field (open parts). Mono-branch parts only.";
}

bool IsovalueDecomposer::accepts(const DecomposeInput& input, std::string* why) const
{
  return hasPlannableEdges(input, why);
}

DecomposeResult IsovalueDecomposer::decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                                     Progress& progress) const
{
  IsoDecompositionOptions options;
  options.pointsPerContour = static_cast<size_t>(values.getInt("points_per_rev"));
  options.levelSpacing = values.internal(schema_, "level_spacing");
  const bool open = input.partClass == PartClass::Open;

  // The field computed upstream, or the thesis's own: harmonic (open) or heat-method distance
  // from the lower edge (closed).
  std::vector<double> computed;
  if (!input.field) {
    SubProgress fieldProgress(progress, 0.0, 0.5, open ? "harmonic field" : "geodesic distance");
    computed =
        open ? harmonicField(input.mesh, input.lower.vertices, input.upper->vertices, fieldProgress)
             : heatGeodesicDistance(input.mesh, input.lower.vertices, HeatDistanceOptions{}, fieldProgress);
  }
  const std::vector<double>& field = input.field ? *input.field : computed;
  SubProgress decomposeProgress(progress, input.field ? 0.0 : 0.5, 1.0, "iso-values");
  IsoDecomposition d =
      decomposeByIsoValues(input.mesh, field, input.lower, open ? &*input.upper : nullptr,
                           open ? std::nullopt : input.closurePoint, options, decomposeProgress);
  DecomposeResult out;
  out.generatrices = std::move(d.generatrices);
  out.warnings = std::move(d.warnings);
  return out;
}

}  // namespace spira

void spira_register_decomposer_isovalue(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::IsovalueDecomposer>());
}
