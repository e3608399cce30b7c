#pragma once

#include "spira/plugin/decomposer.h"

namespace spira {

// decomposer.constant_distance: bent tubes, elbows and nozzles (004_bd0df31205c0c3c0.txt §2.3). Layers
// are laid at a constant local distance from the layer below (the nominal deposit height), on the part's
// own facets, along a guide curve: the tube's centre line from its harmonic field, or the user's polyline.
// On a bend the outer wall is longer than the inner one; a layer keeps its height everywhere and the bend
// takes more layers on the outside instead, so the deposit never has to be modulated. The path is one
// continuous spiral through the layers, or one arc per layer with staggered starts. The part must be one
// tube open at both ends.
class ConstantDistanceDecomposer final : public DecomposerPlugin {
 public:
  ConstantDistanceDecomposer();
  std::string id() const override { return "decomposer.constant_distance"; }
  std::string label() const override { return "Constant distance (tubes)"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  bool accepts(const DecomposeInput& input, std::string* why) const override;

 private:
  DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                   Progress& progress) const override;
  ParamSchema schema_;
};

}  // namespace spira
