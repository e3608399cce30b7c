#pragma once

#include "spira/plugin/decomposer.h"

namespace spira {

// decomposer.geodesic: the thesis's geodesic-distance strategy (000_dbb97c2716e10cc3.txt §3.3.2.2). One
// generatrix per base point, the base points at constant angle around the vertical axis through the base
// centroid; each generatrix is the exact shortest path on the mesh from its base point to the nearest point
// of the upper edge (open parts, Eq. 3.7) or to the closure point (closed parts). Neighbours that
// leave part of the surface uncovered get fill-in generatrices (Eq. 3.8-3.9). Slower than
// decomposer.isovalue, but every generatrix is as short as the surface allows.
class GeodesicDecomposer final : public DecomposerPlugin {
 public:
  GeodesicDecomposer();
  std::string id() const override { return "decomposer.geodesic"; }
  std::string label() const override { return "Geodesic paths"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  bool accepts(const DecomposeInput& input, std::string* why) const override;

 private:
  DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                   Progress& progress) const override;
  ParamSchema schema_;
};

}  // namespace spira
