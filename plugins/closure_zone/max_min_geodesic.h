#pragma once

#include "spira/plugin/closure_finder.h"

namespace spira::closure_zone {

// closure.max_min_geodesic: the closure point of a closed part is the surface point whose
// smallest geodesic distance to the base is largest (thesis Eq. 3.10, paper Eq. 4). The smallest
// distance to all base points is ONE multi-source heat-method field from the whole lower edge,
// so the search is its argmax, refined below the mesh resolution (closure_refinement.h).
class MaxMinGeodesicClosure final : public ClosureFinderPlugin {
 public:
  MaxMinGeodesicClosure();
  std::string id() const override { return "closure.max_min_geodesic"; }
  std::string label() const override { return "Max-min geodesic closure point"; }
  std::string description() const override;
  const ParamSchema& schema() const override { return schema_; }
  ClosureResult find(const ClosureInput& input, const ParamSet& params, Progress& progress) const override;

 private:
  ParamSchema schema_;
};

}  // namespace spira::closure_zone
