#pragma once

#include <optional>
#include <string>
#include <vector>

#include "spira/base/progress.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/substrate_surface.h"
#include "spira/mesh/triangle_mesh.h"
#include "spira/path/spiral_report.h"
#include "spira/path/spiral_settings.h"
#include "spira/path/trajectory.h"
#include "spira/plugin/plugin.h"

namespace spira {

// The process window and bead the spiral will lay on the generatrices, mm.
struct DecomposeWindow {
  double hMin = 0.0, hMax = 0.0;  // thinnest and thickest deposit
  double tolerance = 0.0;         // on both
  double beadWidth = 0.0;
};

// The part as a decomposer sees it: the welded mesh and its free edges.
struct DecomposeInput {
  const TriangleMesh& mesh;
  PartClass partClass = PartClass::Unsupported;
  BoundaryLoop lower;                 // on the substrate
  std::optional<BoundaryLoop> upper;  // open parts only
  std::optional<Vec3> closurePoint;   // closed parts: from a closure finder, if already known
  // Per-vertex scalar field computed upstream (one value per mesh vertex), or nullptr. Closed
  // parts: geodesic distance from the lower edge; open parts: the harmonic field, 0 on the lower
  // edge and 1 on the upper one. Field-based decomposers (decomposer.isovalue) need it; the
  // caller keeps it alive for the duration of the call.
  const std::vector<double>* field = nullptr;
  // What the spiral will lay, for decomposers that can tell from their generatrices alone that no
  // spiral can follow them; zero: not known.
  DecomposeWindow window{};
  // The spiral the planner lays on the generatrices (nominal height, window, start-up, termination), for
  // decomposers that lay the path themselves; nullptr: not known.
  const SpiralSettings* spiral = nullptr;
  // The surface the part is built on when it is not the plane under the lower edge (a pipe, a curved
  // plate), in the part frame; nullptr: the plane.
  const SubstrateSurface* substrate = nullptr;
};

// What a decomposer that lays its path in layers (decomposer.constant_distance) measured on them.
struct LayerStats {
  int layers = 0;                         // deposited layers, the base edge not counted
  double deltaMin = 0.0, deltaMax = 0.0;  // each layer point's distance to the layer below, mm
  double maxKinkDeg = 0.0;                // the largest turning angle between consecutive segments of a layer
  std::vector<double> kinkDeg;            // the same per deposited layer
  int arcStarts = 0;                      // arcs the path is laid in
  std::string output;                     // "spiral" or "layers"
  std::string end;                        // how the part's end was reached: "truncate" or "modulate"
};

struct DecomposeResult {
  Generatrices generatrices;
  std::vector<std::string> warnings;
  // Set by decomposers that lay the path themselves: it replaces the spiral the planner would lay on
  // `generatrices` (which then only show the decomposition).
  std::optional<SpiralResult> path;
  std::optional<LayerStats> layers;
};

class DecomposerPlugin : public Plugin {
 public:
  PluginKind kind() const override { return PluginKind::Decomposer; }
  // Whether this strategy can handle the part; when not, `why` says why in plain words.
  virtual bool accepts(const DecomposeInput& input, std::string* why) const = 0;
  // The one entry point: throws InputError when accepts() refuses the part or when `params`
  // (completed with the schema's defaults) do not fit the schema, then calls decomposeChecked().
  DecomposeResult decompose(const DecomposeInput& input, const ParamSet& params, Progress& progress) const;

 protected:
  // Called by decompose() only, so a strategy checks neither again: accepts(input) is true and
  // `values` holds every key of schema(), each inside its bounds or choices.
  virtual DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                           Progress& progress) const = 0;
};

}  // namespace spira
