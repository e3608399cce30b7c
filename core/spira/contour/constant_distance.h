#pragma once

#include <functional>
#include <vector>

#include "spira/base/transform.h"

namespace spira {

// A tube as a surface S(t, v): t runs along its guide curve (t0 at the base), v in [0, 2 pi) around
// it. 004_bd0df31205c0c3c0.txt Eq. 2.22-2.25.
struct TubeSurface {
  std::function<Vec3(double t, double v)> at;
  // The unit normal at S(t, v), pointing away from the guide, where the surface knows it better than
  // finite differences (a mesh: its normals interpolated across the hit face); empty otherwise.
  std::function<Vec3(double t, double v)> normal;
  double t0 = 0.0;
  double tEnd = 0.0;  // how far the surface may be followed: past the part's nominal end, to finish it
};

struct ConstantDistanceSettings {
  double delta = 2.0;  // mm: the local distance from each layer to the one below, the deposit height
  int pointsPerLayer = 360;
  // Each point looks for the layer below among the points at most this many indices around its own
  // (0: an eighth of the layer), so that it never measures to the tube's opposite wall.
  int window = 0;
  double tolerance = 1e-6;  // mm on the distance
  // Called after each layer with the number of layers so far (the first included): progress, and
  // cancellation by throwing.
  std::function<void(size_t layers)> onLayer;
  // May move a new layer's points along their generatrices (t) before the next layer is laid on it, e.g.
  // to smooth a kink; `points` must stay S(t, v_i).
  std::function<void(std::vector<double>& t, std::vector<Vec3>& points, const std::vector<Vec3>& below)>
      adjustLayer;
};

struct ConstantDistanceLayers {
  std::vector<std::vector<double>> t;     // per layer, per point (point i at v = 2 pi i / N)
  std::vector<std::vector<Vec3>> points;  // S(t, v) of the same
  bool complete = false;  // the last layer reached `until` everywhere; false: the surface ended first
};

// Layers at a constant local distance from the layer below (004_bd0df31205c0c3c0.txt §2.3.1, Eq.
// 2.20-2.21): layer 0 at `firstLayer` (t per point); then each point i of layer n keeps its v_i and takes
// the t > t_{n-1,i} at which its distance to layer n - 1 (closed polyline, point to segment, the
// closing segment included) is delta, found by bracketing and bisection. Layers are added until every
// point of the last one is at t >= `until` (the nominal end; the caller truncates what lies beyond),
// or a point finds no such t before tEnd. Unlike the source, layers are not re-rotated to align
// seams: point i stays at v_i, so the seam stays on the generatrix v = 0.
// Throws InputError for delta <= 0, fewer than 8 points, a first layer of the wrong size or a
// surface without an end past `until`.
ConstantDistanceLayers constantDistanceLayers(const TubeSurface& surface,
                                              const std::vector<double>& firstLayer, double until,
                                              const ConstantDistanceSettings& settings);

// Point i of a layer of n lies at v = 2 pi i / n round the guide.
double layerAngle(int i, int n);

// The angle (degrees) the closed polyline `layer` turns at its point i, between the segments into and out
// of it; 0 where either has no length.
double turningAngleDeg(const std::vector<Vec3>& layer, int i);

// The distance from p to the closed polyline `layer` (point to segment, the closing segment included),
// over the segments whose first point lies within `window` indices of `centre` (all when window <= 0).
double distanceToClosedLayer(const Vec3& p, const std::vector<Vec3>& layer, int centre, int window);

// The largest angle (degrees) between consecutive segments of a closed polyline: the tangent kink the
// method develops on the lagging side of a bend.
double maxTurningAngle(const std::vector<Vec3>& closedLayer);

}  // namespace spira
