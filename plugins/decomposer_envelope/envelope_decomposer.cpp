#include "envelope_decomposer.h"

#include <memory>

#include "axis_choice.h"
#include "envelope_projection.h"
#include "spira/base/error.h"
#include "spira/plugin/decomposer_params.h"
#include "spira/plugin/plugin_registry.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  defs.push_back(
      pointsPerRevolutionParam("Envelope generatrices are spread evenly in angle around the part's axis."));
  defs.push_back(levelSpacingParam("Every generatrix gets the same number of points."));
  defs.push_back(
      choiceParam("axis", "auto", {"auto", "skeleton", "vertical"},
                  {"Projection axis",
                   "What the envelope is projected towards. auto: the part's curve skeleton, or the "
                   "vertical axis through the base centroid when the skeleton runs along it; skeleton: "
                   "always the skeleton; vertical: the vertical axis through the base centroid, no "
                   "skeleton (fastest, for upright parts of revolution).",
                   "Projection"}));
  defs.push_back(
      numberParam("start_angle", 0.0, -360.0, 360.0, "deg",
                  {"Start angle",
                   "Angle about the axis of the first generatrix, where the spiral starts: 0 is +X, "
                   "counted counter-clockwise seen from above.",
                   "Projection"}));
  return ParamSchema(std::move(defs));
}

bool canPlan(const DecomposeInput& input, std::string* why)
{
  auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (input.partClass == PartClass::Closed)
    return no(
        "envelope projection plans open parts only (two free edges); use --strategy isovalue for "
        "closed parts");
  if (input.partClass != PartClass::Open)
    return no("the part is not open: it needs exactly two free edges, one on the substrate and one on top");
  if (!input.upper || input.upper->vertices.size() < 3) return no("the open part has no upper edge");
  if (input.lower.vertices.size() < 3) return no("the part has no lower edge");
  return true;
}

AxisMode axisMode(const std::string& value)
{
  if (value == "skeleton") return AxisMode::Skeleton;
  if (value == "vertical") return AxisMode::Vertical;
  return AxisMode::Auto;
}

}  // namespace

EnvelopeDecomposer::EnvelopeDecomposer() : schema_(makeSchema()) {}

std::string EnvelopeDecomposer::description() const
{
  return "Envelope generatrices on a cylinder around the part, projected horizontally onto it towards the "
         "skeleton point at the same height. Open parts without overhangs only.";
}

bool EnvelopeDecomposer::accepts(const DecomposeInput& input, std::string* why) const
{
  return canPlan(input, why);
}

DecomposeResult EnvelopeDecomposer::decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                                     Progress& progress) const
{
  EnvelopeOptions options;
  options.generatrixCount = static_cast<size_t>(values.getInt("points_per_rev"));
  options.pointSpacing = values.internal(schema_, "level_spacing");
  options.startAngle = values.internal(schema_, "start_angle");
  const AxisMode mode = axisMode(values.getString("axis"));

  SubProgress axisProgress(progress, 0.0, mode == AxisMode::Vertical ? 0.0 : 0.4, "skeleton");
  const AxisChoice axis = chooseProjectionAxis(input.mesh, input.lower, mode, axisProgress);
  SubProgress projectionProgress(progress, mode == AxisMode::Vertical ? 0.0 : 0.4, 1.0,
                                 "envelope projection");
  EnvelopeDecomposition d = decomposeByEnvelopeProjection(input.mesh, input.lower, *input.upper, axis.axis,
                                                          options, projectionProgress);
  DecomposeResult out;
  out.generatrices = std::move(d.generatrices);
  out.warnings = axis.warnings;
  out.warnings.insert(out.warnings.end(), d.warnings.begin(), d.warnings.end());
  return out;
}

}  // namespace spira

void spira_register_decomposer_envelope(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::EnvelopeDecomposer>());
}
