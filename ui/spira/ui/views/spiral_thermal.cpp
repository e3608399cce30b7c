// SpiralLayer's thermal channels: the thermal stage's values per point of the path.
#include <algorithm>

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>

#include "spira/document/stage_reports.h"
#include "spira/document/thermal_result.h"
#include "spira/ui/views/spiral_layer.h"

namespace spira::ui {

void SpiralLayer::setThermal(const ThermalStageResult* thermal, const ThermalStageReport* report)
{
  hasThermal_ = thermal && hasTrajectory() && static_cast<long long>(thermal->pointCount()) == pointCount_ &&
                thermal->interpass.size() == thermal->pointCount() &&
                thermal->risk.size() == thermal->pointCount();
  meltingC_ = report ? report->meltingTemperature : 0.0;
  interpassLimitC_ = report ? report->interpassLimit : 0.0;
  riskPoints_ = 0;
  for (const char* name : {"peak_temperature", "interpass_temperature", "collapse_risk"})
    path_->GetPointData()->RemoveArray(name);
  if (hasThermal_) {
    const vtkIdType n = pointCount_;
    vtkNew<vtkDoubleArray> peak, interpass, risk;
    peak->SetName("peak_temperature");
    interpass->SetName("interpass_temperature");
    risk->SetName("collapse_risk");
    for (vtkDoubleArray* a : {peak.Get(), interpass.Get(), risk.Get()}) a->SetNumberOfValues(n);
    for (vtkIdType i = 0; i < n; ++i) {
      const auto k = static_cast<size_t>(i);
      peak->SetValue(i, thermal->peak[k]);
      interpass->SetValue(i, thermal->interpass[k]);
      risk->SetValue(i, thermal->risk[k] ? 1.0 : 0.0);
      riskPoints_ += thermal->risk[k] ? 1 : 0;
    }
    for (vtkDoubleArray* a : {peak.Get(), interpass.Get(), risk.Get()}) path_->GetPointData()->AddArray(a);
    std::vector<double> sorted = thermal->peak;
    std::sort(sorted.begin(), sorted.end());
    const auto at = [&](double q) {
      return sorted[static_cast<size_t>(q * static_cast<double>(sorted.size() - 1))];
    };
    peakScale_ = sorted.empty() ? std::make_pair(0.0, 0.0) : std::make_pair(at(0.02), at(0.98));
  }
  if (!channelAvailable(channel_)) channel_ = SpiralChannel::Height;
  if (!hasTrajectory()) return;
  rebuildCells();
  updateColours();
  updateVisibility();
}

}  // namespace spira::ui
