#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <vector>

namespace spira {

// A closed triangle surface as plain arrays (vertex positions, faces as vertex indices).
struct FlowSurface {
  std::vector<std::array<double, 3>> vertices;
  std::vector<std::array<int, 3>> faces;
};

// CGAL's Mean_curvature_flow_skeletonization parameters (see SkeletonOptions).
struct FlowSettings {
  size_t maxIterations = 150;
  double areaVariation = 1e-4;
  bool mediallyCentered = true;
  double qualitySpeedTradeoff = 0.1;
  double medialSpeedTradeoff = 0.2;
};

struct FlowSkeleton {
  std::vector<std::array<double, 3>> nodes;
  std::vector<std::array<int, 2>> edges;
  size_t iterations = 0;
  bool converged = false;
};

// Contracts `surface` by CGAL's mean curvature flow, one step at a time, until one step changes the
// meso-skeleton's area by less than areaVariation times the original area or maxIterations steps
// ran, and returns the curve skeleton it collapses to. `beforeStep` runs before every step (it may
// throw to cancel); `afterStep` gets the meso-skeleton's area over the original area. The result
// depends on `surface` and `settings` alone: the flow's edge collapses run in the mesh's own
// order, not in the order of the addresses its elements got, so every run gives the same skeleton.
//
// This is the one translation unit that instantiates CGAL's flow, and it takes and returns plain
// arrays on purpose: compiled in one unit with the surface simplification and the rest of the
// skeleton code, GCC 12 inlines std::set::swap into the flow's collapse_short_edges() so that it
// reports a -Wdangling-pointer false positive there; on its own the flow compiles cleanly, with no
// pragma or warning flag.
FlowSkeleton runMeanCurvatureFlow(const FlowSurface& surface, const FlowSettings& settings,
                                  const std::function<void()>& beforeStep,
                                  const std::function<void(double)>& afterStep);

}  // namespace spira
