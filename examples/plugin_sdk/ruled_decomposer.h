#pragma once

#include "spira/plugin/decomposer.h"

namespace spira::example {

// The worked example of docs/architecture.md: a decomposition strategy for open ruled walls
// (cylinders, cones, extruded profiles). Each generatrix is the straight segment from the lower
// edge to the upper edge at one angle about the part's axis; on a ruled wall it lies on the surface.
class RuledDecomposer : public DecomposerPlugin {
 public:
  std::string id() const override { return "decomposer.example_ruled"; }
  std::string label() const override { return "Ruled wall (example)"; }
  std::string description() const override;
  const ParamSchema& schema() const override;
  bool accepts(const DecomposeInput& input, std::string* why) const override;

 private:
  DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                   Progress& progress) const override;
};

}  // namespace spira::example
