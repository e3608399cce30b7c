#pragma once

#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/contour/constant_distance.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/trajectory.h"

namespace spira {

enum class TubeEnd {
  // Layers are laid past the upper edge on the tube continued along its guide, then cut by the part's
  // end: the last layers are partial (004_bd0df31205c0c3c0.txt §2.3.2).
  Truncate,
  // The last layers are re-laid between a constant-distance layer and the upper edge at a height
  // modulated inside the process window, so that the last one lies on the edge.
  Modulate,
};

struct TubeLayerSettings {
  double delta = 2.0;  // mm: the nominal deposit height
  double hMin = 1.8, hMax = 2.2, tolerance = 0.01;
  int points = 360;  // per layer
  TubeEnd end = TubeEnd::Truncate;
  // Layers turning more than this (deg) at a point are smoothed there (0: never): the points around the
  // kink move along their generatrices towards their neighbours as far as their deposit stays in the window.
  double smoothKinkDeg = 0.0;
};

// A meshed tube decomposed into layers: layer 0 is the base edge, each later one a deposit above it.
struct TubeLayers {
  TubeSurface surface;                // the part's surface, continued straight past its upper edge
  std::function<Vec3(double)> guide;  // the guide curve, t its arc length from the guide's first point
  std::vector<double> top;            // t of the upper edge at each point
  std::vector<std::vector<double>> t;
  std::vector<std::vector<Vec3>> points;
  std::vector<std::vector<char>> kept;  // per point: on the part (a truncated layer keeps fewer)
  int constantLayers = 0;               // layers at delta from the one below (after them: the modulated end)
  double radiusMin = 0.0;               // the tube's narrowest mean radius about the guide, mm
  int smoothedPoints = 0;               // points moved to smooth kinks
  std::vector<std::string> warnings;
};

// Lays constant-distance layers (constant_distance.h) on `mesh` along the guide through `centreLine`
// (base end first), from the base edge to the upper edge, and finishes them as `settings.end` says.
// Throws InputError for a guide that leaves the part, a delta not smaller than the tube's radius, and
// layers that cannot be continued on the part (a hole in the wall).
TubeLayers layTubeLayers(const TriangleMesh& mesh, const Polyline& centreLine, double reach,
                         const TubeLayerSettings& settings, Progress& progress);

// The distance of each point of `layer` to the closed polyline `below` (the layer under it), over the
// points where `use` is set (all when empty).
std::vector<double> layerDistances(const std::vector<Vec3>& layer, const std::vector<Vec3>& below,
                                   const std::vector<char>& use = {});

}  // namespace spira
