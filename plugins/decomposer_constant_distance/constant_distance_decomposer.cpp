#include "constant_distance_decomposer.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "layer_path.h"
#include "spira/base/error.h"
#include "spira/plugin/decomposer_params.h"
#include "spira/plugin/plugin_registry.h"
#include "tube_centre_line.h"
#include "tube_layers.h"

namespace spira {

namespace {

ParamSchema makeSchema()
{
  std::vector<ParamDef> defs;
  // A tube is narrower than the shells the other strategies plan: at 360 points a 30 mm tube's points lie
  // 0.26 mm apart, closer than a revolution's seam drifts along a bend.
  ParamDef points =
      pointsPerRevolutionParam("Here the points of each layer, evenly spread in angle about the guide.");
  points.defaultValue = std::int64_t(180);
  defs.push_back(points);
  defs.push_back(choiceParam(
      "output", "spiral", {"spiral", "layers"},
      {"Path",
       "spiral: one continuous spiral through the layers, one arc start; layers: one arc per layer, "
       "its start staggered from the one below.",
       "Constant distance"}));
  defs.push_back(choiceParam("stagger", "golden", {"golden", "constant", "kink", "none"},
                             {"Staggered starts",
                              "Where each layer's arc starts (layers path): golden: 137.5 deg further round "
                              "than the layer below, never twice near the same place; constant: 'Stagger "
                              "angle' further round; kink: where the layer turns most, so its kink becomes "
                              "the arc's ends; none: all "
                              "on one line.",
                              "Constant distance"}));
  defs.push_back(
      numberParam("stagger_angle", 30.0, -360.0, 360.0, "deg",
                  {"Stagger angle", "How far round each layer starts from the one below (constant stagger).",
                   "Constant distance"}));
  defs.push_back(choiceParam(
      "end", "truncate", {"truncate", "modulate"},
      {"Part end",
       "How the layers meet the upper edge, which they do not reach all at once on a bend. truncate: layers "
       "are laid past the edge and cut by it (partial last layers, more arc starts); modulate: the last "
       "layers are re-laid at heights inside the process window so that the last one lies on the edge, where "
       "the window is wide enough for the edge's slant across the layers.",
       "Constant distance"}));
  defs.push_back(numberParam("smooth_kink", 0.0, 0.0, 180.0, "deg",
                             {"Smooth kinks above",
                              "On a bend the layers develop a corner on the side that lags "
                              "(004_bd0df31205c0c3c0.txt §2.3: up to 113 deg "
                              "on a quarter torus), which slows the robot and thickens the wall there. "
                              "Points where a layer turns more "
                              "than this are moved towards their neighbours as far as their deposit stays "
                              "inside the process window. "
                              "0: layers kept at the constant distance.",
                              "Constant distance"}));
  defs.push_back(
      pathParam("guide", {"Guide curve",
                          "A CSV of the tube's centre line (x,y,z in mm, one point per line, base end "
                          "first). Empty: taken from the part.",
                          "Constant distance"}));
  return ParamSchema(std::move(defs));
}

Stagger staggerOf(const std::string& v)
{
  if (v == "none") return Stagger::None;
  if (v == "constant") return Stagger::Constant;
  if (v == "kink") return Stagger::Kink;
  return Stagger::Golden;
}

}  // namespace

ConstantDistanceDecomposer::ConstantDistanceDecomposer() : schema_(makeSchema()) {}

std::string ConstantDistanceDecomposer::description() const
{
  return "Layers at a constant distance (the deposit height) from the layer below, along the tube's guide "
         "curve: bent tubes without modulating the deposit. Open tubes only.";
}

bool ConstantDistanceDecomposer::accepts(const DecomposeInput& input, std::string* why) const
{
  auto no = [&](const std::string& reason) {
    if (why) *why = reason;
    return false;
  };
  if (input.partClass == PartClass::Closed)
    return no(
        "the part is closed at the top; constant-distance layers need a tube open at both ends: use "
        "--strategy isovalue for closed parts");
  if (input.partClass != PartClass::Open || !input.upper)
    return no("the part is not a tube: it needs exactly two free edges, one on the substrate and one on top");
  if (input.lower.vertices.size() < 3 || input.upper->vertices.size() < 3)
    return no("the tube's free edges have fewer than 3 points");
  if (!input.field || input.field->size() != input.mesh.vertices.size())
    return no("the part's harmonic field is missing (the planner computes it)");
  if (!input.spiral || !(input.spiral->h > 0.0)) return no("the nominal deposit height is not known");
  return true;
}

DecomposeResult ConstantDistanceDecomposer::decomposeChecked(const DecomposeInput& input,
                                                             const ParamSet& values, Progress& progress) const
{
  const std::string guideFile = values.getString("guide");
  Polyline line = guideFile.empty() ? centreLineFromField(input.mesh, *input.field, input.lower, *input.upper)
                                    : readGuideCsv(guideFile);
  // Base end first, whichever way the user wrote it.
  const Vec3 base = loopCentroid(input.mesh, input.lower);
  if ((line.back() - base).norm() < (line.front() - base).norm()) std::reverse(line.begin(), line.end());
  progress.checkCancel();

  const SpiralSettings& spiral = *input.spiral;
  TubeLayerSettings s;
  s.delta = spiral.h;
  s.hMin = spiral.hMin;
  s.hMax = spiral.hMax;
  s.tolerance = spiral.heightTolerance * spiral.h;
  s.points = int(values.getInt("points_per_rev"));
  s.end = values.getString("end") == "modulate" ? TubeEnd::Modulate : TubeEnd::Truncate;
  s.smoothKinkDeg = values.getDouble("smooth_kink");
  const double radius = std::max(loopRadius(input.mesh, input.lower), loopRadius(input.mesh, *input.upper));
  SubProgress layerProgress(progress, 0.0, 0.8, "constant-distance layers");
  const TubeLayers layers = layTubeLayers(input.mesh, line, 3.0 * radius + 4.0 * spiral.h, s, layerProgress);

  LayerPathSettings path;
  path.spiral = values.getString("output") == "spiral";
  path.stagger = staggerOf(values.getString("stagger"));
  path.staggerAngle = values.internal(schema_, "stagger_angle");
  path.window = spiral;
  path.substrate = input.substrate && !input.substrate->isPlane() ? input.substrate : nullptr;
  SubProgress pathProgress(progress, 0.8, 1.0, "path through the layers");
  LaidLayers laid = layPath(layers, path, pathProgress);
  laid.stats.output = values.getString("output");
  laid.stats.end = values.getString("end");

  DecomposeResult out;
  out.generatrices = std::move(laid.generatrices);
  out.generatrices.guide = line;
  out.warnings = layers.warnings;
  if (layers.smoothedPoints > 0)
    out.warnings.push_back(std::to_string(layers.smoothedPoints) +
                           " layer point(s) moved off the constant distance "
                           "to smooth kinks sharper than " +
                           std::to_string(int(std::lround(s.smoothKinkDeg))) + " deg");
  out.path = std::move(laid.path);
  out.layers = std::move(laid.stats);
  return out;
}

}  // namespace spira

void spira_register_decomposer_constant_distance(spira::PluginRegistry& registry)
{
  registry.add(std::make_unique<spira::ConstantDistanceDecomposer>());
}
