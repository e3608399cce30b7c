#pragma once

#include <vector>

#include <vtkNew.h>

#include "spira/base/transform.h"
#include "spira/ui/views/color_maps.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira {
struct PointCloud;
struct DeviationStats;
}  // namespace spira

namespace spira::ui {

// A scan compared with the part: its points where the alignment put them, coloured by their signed
// deviation from the part (blue inside, green on it, red outside, the scale symmetric about 0 and
// reaching the 95th percentile of the magnitudes), with a legend that gives the statistics.
class ScanLayer {
 public:
  explicit ScanLayer(vtkRenderer* renderer);
  ~ScanLayer();

  // The cloud in the part's frame; an empty cloud clears the layer. Without deviations (a scan not yet
  // placed on the part) the points are drawn plain grey, with no legend.
  void setScan(const PointCloud& cloud, const std::vector<double>& deviation, const DeviationStats& stats,
               const Transform& T_world_part);
  void setVisible(bool on);
  bool visible() const { return visible_; }
  bool hasScan() const { return count_ > 0; }
  bool aligned() const { return aligned_; }
  size_t pointCount() const { return count_; }
  double scaleLimit() const { return limit_; }  // mm: the legend runs from -limit to +limit
  const ColorLegend& legend() const { return legend_; }
  vtkActor* actor() const { return actor_; }

 private:
  void update();

  vtkNew<vtkPolyData> cloud_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  ColorLegend legend_;
  size_t count_ = 0;
  bool aligned_ = false;
  double limit_ = 0.0;
  bool visible_ = true;
};

}  // namespace spira::ui
