#pragma once

#include <optional>
#include <vector>

#include <QString>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/ui/views/color_maps.h"

#include "spira/base/transform.h"
#include "spira/pipeline/document_plan.h"

class vtkActor;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;
class vtkTextActor;
class vtkTubeFilter;

namespace spira {
struct KinematicsResult;
struct ThermalStageReport;
struct ThermalStageResult;
struct Trajectory;
}  // namespace spira

namespace spira::ui {

// What the spiral is coloured by.
enum class SpiralChannel {
  Height,
  TravelSpeed,
  WireFeed,
  Revolution,
  Dexterity,
  LimitMargin,
  PeakTemperature,
  InterpassTemperature,
  CollapseRisk
};
constexpr int kSpiralChannelCount = 9;

struct SpiralChannelInfo {
  const char* array;             // point-data array name
  QString name;                  // legend title
  QString unit;                  // shown unit ("" for counts)
  bool needsProcess;             // only with the process stage's channels
  bool needsKinematics = false;  // only with the kinematics stage (a cell)
  bool needsThermal = false;     // only with the thermal stage
};
SpiralChannelInfo spiralChannelInfo(SpiralChannel c);

// The planned spiral in the 3D view: a polyline (or a tube on demand) coloured by a channel with
// its legend, the points whose deposit height leaves the process window as red dots, and the
// build cut at a chosen revolution (the part as it stands after that layer).
class SpiralLayer {
 public:
  explicit SpiralLayer(vtkRenderer* renderer);
  ~SpiralLayer();

  // `path` carries the channels to show (the process stage's trajectory when there is one,
  // otherwise the spiral's, without speeds); `hasSpeeds` says which. Null clears. Positions are
  // in the part frame, drawn where T_world_part places them.
  void setTrajectory(const Trajectory* path, bool hasSpeeds, std::optional<PlanWindow> window,
                     const Transform& T_world_part = Transform::Identity());
  bool hasTrajectory() const { return pointCount_ > 0; }
  // The robot motion solved for the path (null, or a different point count: none). Adds the
  // dexterity and joint-limit margin channels and marks unreachable or colliding points in red.
  void setKinematics(const KinematicsResult* kinematics);
  bool hasKinematics() const { return hasKinematics_; }
  long long kinematicFlagCount() const { return static_cast<long long>(kinematicFlags_.size()); }
  vtkActor* kinematicFlagActor() const { return kinematicFlagActor_; }
  // The thermal stage's values per point (null, or a different point count - a re-planned path -:
  // none): peak and interpass temperature, collapse risk. The report gives the melting temperature
  // and the interpass limit the legend marks.
  void setThermal(const ThermalStageResult* thermal, const ThermalStageReport* report);
  bool hasThermal() const { return hasThermal_; }
  bool channelAvailable(SpiralChannel c) const;
  // Returns false (and keeps the channel) when `c` is not available.
  bool setChannel(SpiralChannel c);
  SpiralChannel channel() const { return channel_; }
  std::pair<double, double> channelRange() const { return range_; }

  void setVisible(bool on);
  bool visible() const { return visible_; }
  // Hidden while the part itself shows what the spiral would cover (the temperature field), without
  // changing the user's choice (visible()).
  void setHiddenByPart(bool hidden);
  void setTube(bool on);
  bool tube() const { return tube_; }

  // Shows the build up to and including revolution `last` (clamped to the plan's revolutions).
  void setRevolutionLimit(int last);
  int revolutionLimit() const { return limit_; }
  // Revolution indices in the path (a closed part's closure point is the last one, alone).
  int revolutionCount() const { return revolutions_; }
  // Whether the last revolution index holds a single point: the closure point of a closed part.
  bool endsOnAPoint() const { return endsOnAPoint_; }
  // Points drawn, and window violations drawn, at the current limit.
  long long shownPointCount() const { return shownPoints_; }
  long long shownViolationCount() const { return shownViolations_; }
  long long violationCount() const { return static_cast<long long>(violations_.size()); }
  // Arc length along the path up to the last point shown (the latest in build order), mm.
  double shownLength() const;

  const ColorLegend& legend() const { return legend_; }
  vtkPolyDataMapper* mapper() const { return mapper_; }
  vtkActor* actor() const { return actor_; }
  vtkActor* violationActor() const { return violationActor_; }

 private:
  void rebuildCells();
  void updateColours();
  void updateVisibility();
  QString thermalLegendNote() const;

  vtkRenderer* renderer_;
  vtkNew<vtkPolyData> path_;
  vtkNew<vtkPolyData> shown_;
  vtkNew<vtkTubeFilter> tubeFilter_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  vtkNew<vtkPolyData> violationPoints_;
  vtkNew<vtkPolyDataMapper> violationMapper_;
  vtkNew<vtkActor> violationActor_;
  vtkNew<vtkPolyData> kinematicFlagPoints_;
  vtkNew<vtkActor> kinematicFlagActor_;
  std::vector<long long> kinematicFlags_;  // unreachable or colliding point indices
  bool hasKinematics_ = false;
  bool hasThermal_ = false;
  double meltingC_ = 0.0, interpassLimitC_ = 0.0;
  std::pair<double, double> peakScale_{0.0, 0.0};  // C, 2nd and 98th percentile of the peaks
  long long riskPoints_ = 0;
  ColorLegend legend_;
  vtkNew<vtkTextActor> banner_;

  std::vector<int> revolution_;        // per point
  std::vector<int> subPath_;           // per point: TrajectoryPoint::path
  std::vector<double> abscissa_;       // per point, mm
  std::vector<long long> violations_;  // point indices outside the window
  std::optional<PlanWindow> window_;
  long long pointCount_ = 0;
  long long shownPoints_ = 0;
  long long shownLast_ = -1;  // index of the last point shown
  long long shownViolations_ = 0;
  int revolutions_ = 0;
  int limit_ = 0;
  bool hasSpeeds_ = false;
  bool endsOnAPoint_ = false;
  bool visible_ = true;
  bool hiddenByPart_ = false;
  bool tube_ = false;
  double tubeRadius_ = 0.8;
  SpiralChannel channel_ = SpiralChannel::Height;
  std::pair<double, double> range_{0.0, 1.0};
};

}  // namespace spira::ui
