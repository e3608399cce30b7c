#pragma once

#include "spira/plugin/decomposer.h"

namespace spira {

// decomposer.isovalue: the thesis's recommended strategy (000_dbb97c2716e10cc3.txt §3.3.2.4). Generatrices
// follow the iso-contours of a per-vertex scalar field: DecomposeInput::field when the caller computed one,
// otherwise the thesis's own, computed here: the heat-method geodesic distance from the lower edge
// on closed parts, the harmonic field (0 on the lower edge, 1 on the upper) on open parts.
// Mono-branch parts only: a field whose contour count changes is refused.
class IsovalueDecomposer final : public DecomposerPlugin {
 public:
  IsovalueDecomposer();
  std::string id() const override { return "decomposer.isovalue"; }
  std::string label() const override { return "Iso-values"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  bool accepts(const DecomposeInput& input, std::string* why) const override;

 private:
  DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                   Progress& progress) const override;
  ParamSchema schema_;
};

}  // namespace spira
