#pragma once

#include "spira/base/progress.h"
#include "spira/path/spiral_report.h"
#include "spira/path/spiral_settings.h"
#include "spira/plugin/decomposer.h"
#include "tube_layers.h"

namespace spira {

// Where each layer's arc starts and stops (004_bd0df31205c0c3c0.txt §2.4, Fig. 2.20: stacked arc
// starts and stops make a defect column).
enum class Stagger {
  None,      // every layer starts at v = 0
  Constant,  // each layer starts a fixed angle further round than the one below
  Golden,    // each layer starts a golden angle (137.5 deg) further round: never twice near the same place
  Kink,      // each layer starts and ends where it turns most: its kink becomes the arc's two ends
};

struct LayerPathSettings {
  bool spiral = true;  // one continuous spiral through the layers; false: one arc per layer
  Stagger stagger = Stagger::Golden;
  double staggerAngle = 0.5235987755982988;  // rad, for Stagger::Constant
  SpiralSettings window;                     // nominal height, window, start-up and termination
  // The surface under the base edge when it is not the plane there (a pipe, a curved plate); nullptr:
  // the plane. The first beads are measured down to it.
  const SubstrateSurface* substrate = nullptr;
};

struct LaidLayers {
  SpiralResult path;
  LayerStats stats;
  Generatrices generatrices;  // the layers' points per generatrix (v fixed), for display
};

// The deposition path through `layers`.
// Layers: each layer a closed arc from its staggered start back to it (a truncated layer: one arc per
// piece on the part), each arc its own sub-path (TrajectoryPoint::path), so it gets its own arc start.
// Spiral: the spiral builder's start-up, revolutions and termination (spiral_builder.h) laid in level
// space, where generatrix i climbs by each layer's measured distance at i, then mapped onto the tube:
// a point between layers k and k + 1 lies on the surface at the t interpolated between them at its v. On
// constant-distance layers every generatrix climbs delta per layer, so the spiral's deposit is constant
// apart from its start-up and end. A truncated end cuts the spiral where it leaves the part; each piece
// left on the part becomes an arc of its own.
// Frames come from the surface normal (∂S/∂t × ∂S/∂v) and the path (spiral_frames.h), heights are each
// point's rise along b over the point of the layer or revolution under it.
LaidLayers layPath(const TubeLayers& layers, const LayerPathSettings& settings, Progress& progress);

}  // namespace spira
