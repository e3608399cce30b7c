#pragma once

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace spira::ui {

// The substrate plate drawn under a part: a square plane at height `z`, centred under the part
// and larger than its footprint, plus grid lines at a round spacing (1, 2 or 5 x 10^k mm) so a
// user can read sizes at a glance.
struct SubstrateGrid {
  vtkSmartPointer<vtkPolyData> plane;  // one quad
  vtkSmartPointer<vtkPolyData> lines;  // grid lines, including the border
  double spacing = 0.0;                // mm between grid lines
  double halfSize = 0.0;               // half the plate's side, mm
};

// `bounds` is {xmin, xmax, ymin, ymax, zmin, zmax} of the part; an empty or degenerate box gets
// a 100 mm plate around the origin.
SubstrateGrid makeSubstrateGrid(const double bounds[6], double z);

// The round spacing (1, 2 or 5 x 10^k) nearest above `span / targetCells`.
double niceGridSpacing(double span, int targetCells);

}  // namespace spira::ui
