#include "spira/ui/views/substrate_grid.h"

#include <algorithm>
#include <cmath>

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

namespace spira::ui {

double niceGridSpacing(double span, int targetCells)
{
  const double raw = span / std::max(1, targetCells);
  if (!(raw > 0.0) || !std::isfinite(raw)) return 10.0;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    if (m * decade >= raw * (1.0 - 1e-9)) return m * decade;
  }
  return 10.0 * decade;
}

SubstrateGrid makeSubstrateGrid(const double bounds[6], double z)
{
  double cx = 0.0, cy = 0.0, footprint = 100.0;
  const bool valid = bounds[0] <= bounds[1] && bounds[2] <= bounds[3];
  if (valid) {
    cx = 0.5 * (bounds[0] + bounds[1]);
    cy = 0.5 * (bounds[2] + bounds[3]);
    footprint = std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]);
    // A tall, slender part still deserves a plate that reads as a plate.
    footprint = std::max(footprint, 0.5 * (bounds[5] - bounds[4]));
    if (!(footprint > 0.0)) footprint = 100.0;
  }
  SubstrateGrid grid;
  grid.spacing = niceGridSpacing(1.6 * footprint, 12);
  const int cellsPerHalf = static_cast<int>(std::ceil(0.8 * footprint / grid.spacing));
  grid.halfSize = cellsPerHalf * grid.spacing;
  // Snap the centre to the grid so lines fall on round coordinates.
  cx = std::round(cx / grid.spacing) * grid.spacing;
  cy = std::round(cy / grid.spacing) * grid.spacing;
  const double x0 = cx - grid.halfSize, x1 = cx + grid.halfSize;
  const double y0 = cy - grid.halfSize, y1 = cy + grid.halfSize;

  vtkNew<vtkPoints> quadPoints;
  quadPoints->InsertNextPoint(x0, y0, z);
  quadPoints->InsertNextPoint(x1, y0, z);
  quadPoints->InsertNextPoint(x1, y1, z);
  quadPoints->InsertNextPoint(x0, y1, z);
  vtkNew<vtkCellArray> quad;
  const vtkIdType ids[4] = {0, 1, 2, 3};
  quad->InsertNextCell(4, ids);
  grid.plane = vtkSmartPointer<vtkPolyData>::New();
  grid.plane->SetPoints(quadPoints);
  grid.plane->SetPolys(quad);

  vtkNew<vtkPoints> linePoints;
  vtkNew<vtkCellArray> lines;
  auto addLine = [&](double ax, double ay, double bx, double by) {
    const vtkIdType a = linePoints->InsertNextPoint(ax, ay, z);
    const vtkIdType b = linePoints->InsertNextPoint(bx, by, z);
    const vtkIdType seg[2] = {a, b};
    lines->InsertNextCell(2, seg);
  };
  for (int i = -cellsPerHalf; i <= cellsPerHalf; ++i) {
    const double t = i * grid.spacing;
    addLine(cx + t, y0, cx + t, y1);
    addLine(x0, cy + t, x1, cy + t);
  }
  grid.lines = vtkSmartPointer<vtkPolyData>::New();
  grid.lines->SetPoints(linePoints);
  grid.lines->SetLines(lines);
  return grid;
}

}  // namespace spira::ui
