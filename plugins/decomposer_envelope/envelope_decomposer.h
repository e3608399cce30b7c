#pragma once

#include "spira/plugin/decomposer.h"

namespace spira {

// decomposer.envelope_projection: the thesis's first strategy (000_dbb97c2716e10cc3.txt §3.3.2.1), for open
// parts without overhangs. Vertical envelope generatrices around the part, cut to the free edges, are
// projected horizontally towards the part's axis (its skeleton, or the vertical line through the base
// centroid) onto the nearest surface hit. Fast and faithful on parts of revolution and sloped
// rims; refuses closed parts, multi-branch parts and overhangs (the surface under an overhang
// gets no projection) with a message naming where it fails.
class EnvelopeDecomposer final : public DecomposerPlugin {
 public:
  EnvelopeDecomposer();
  std::string id() const override { return "decomposer.envelope_projection"; }
  std::string label() const override { return "Envelope projection"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  bool accepts(const DecomposeInput& input, std::string* why) const override;

 private:
  DecomposeResult decomposeChecked(const DecomposeInput& input, const ParamSet& values,
                                   Progress& progress) const override;
  ParamSchema schema_;
};

}  // namespace spira
