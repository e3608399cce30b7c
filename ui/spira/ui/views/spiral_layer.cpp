#include "spira/ui/views/spiral_layer.h"

#include <algorithm>
#include <cmath>

#include <QLocale>
#include <QObject>

#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLookupTable.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTubeFilter.h>

#include "spira/base/units.h"
#include "spira/document/kinematics_result.h"
#include "spira/path/trajectory.h"
#include "spira/ui/views/color_maps.h"

namespace spira::ui {

namespace {

// Deposits outside the process window: a colour none of the colour maps uses.
constexpr double kOutsideColour[3] = {1.0, 0.0, 0.9};

vtkSmartPointer<vtkDoubleArray> channelArray(const char* name, vtkIdType n)
{
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name);
  a->SetNumberOfValues(n);
  return a;
}

}  // namespace

SpiralChannelInfo spiralChannelInfo(SpiralChannel c)
{
  switch (c) {
    case SpiralChannel::Height:
      return {"height", QObject::tr("Deposit height"), QStringLiteral("mm"), false, false};
    case SpiralChannel::TravelSpeed:
      return {"travel_speed", QObject::tr("Travel speed"), QStringLiteral("mm/s"), true, false};
    case SpiralChannel::WireFeed:
      return {"wire_feed", QObject::tr("Wire-feed speed"), QStringLiteral("m/min"), true, false};
    case SpiralChannel::Revolution:
      return {"revolution", QObject::tr("Revolution"), QString(), false, false};
    case SpiralChannel::Dexterity:
      return {"dexterity", QObject::tr("Dexterity"), QString(), false, true};
    case SpiralChannel::LimitMargin:
      return {"limit_margin", QObject::tr("Joint-limit margin"), QStringLiteral("deg"), false, true};
    case SpiralChannel::PeakTemperature:
      return {"peak_temperature", QObject::tr("Peak temperature"), QStringLiteral("°C"), false, false, true};
    case SpiralChannel::InterpassTemperature:
      return {"interpass_temperature",
              QObject::tr("Interpass temperature"),
              QStringLiteral("°C"),
              false,
              false,
              true};
    case SpiralChannel::CollapseRisk:
      return {"collapse_risk", QObject::tr("Collapse risk"), QString(), false, false, true};
  }
  return {"height", QObject::tr("Deposit height"), QStringLiteral("mm"), false, false};
}

SpiralLayer::SpiralLayer(vtkRenderer* renderer)
    : renderer_(renderer), legend_(renderer, ColorLegend::Side::Right)
{
  tubeFilter_->SetInputData(shown_);
  tubeFilter_->SetNumberOfSides(10);
  tubeFilter_->CappingOn();
  mapper_->SetInputData(shown_);
  mapper_->SetScalarModeToUsePointFieldData();
  mapper_->InterpolateScalarsBeforeMappingOn();
  mapper_->UseLookupTableScalarRangeOff();
  // The path lies on the part's surface: keep it in front of the triangles it runs on.
  mapper_->SetRelativeCoincidentTopologyLineOffsetParameters(-1.0, -30.0);
  actor_->SetMapper(mapper_);
  actor_->GetProperty()->SetLineWidth(2.0);
  actor_->GetProperty()->SetAmbient(0.25);
  actor_->GetProperty()->SetSpecular(0.2);
  actor_->VisibilityOff();
  renderer_->AddActor(actor_);

  violationMapper_->SetInputData(violationPoints_);
  violationMapper_->ScalarVisibilityOff();
  violationActor_->SetMapper(violationMapper_);
  vtkProperty* vp = violationActor_->GetProperty();
  vp->SetColor(kOutsideColour[0], kOutsideColour[1], kOutsideColour[2]);
  vp->SetPointSize(6.0);
  vp->SetRenderPointsAsSpheres(true);
  violationActor_->VisibilityOff();
  renderer_->AddActor(violationActor_);
  vtkNew<vtkPolyDataMapper> flagMapper;
  flagMapper->SetInputData(kinematicFlagPoints_);
  flagMapper->ScalarVisibilityOff();
  kinematicFlagActor_->SetMapper(flagMapper);
  kinematicFlagActor_->GetProperty()->SetColor(0.95, 0.05, 0.05);
  kinematicFlagActor_->GetProperty()->SetPointSize(7.0);
  kinematicFlagActor_->GetProperty()->SetRenderPointsAsSpheres(true);
  kinematicFlagActor_->VisibilityOff();
  renderer_->AddActor(kinematicFlagActor_);

  vtkTextProperty* t = banner_->GetTextProperty();
  t->SetFontSize(15);
  t->BoldOn();
  t->ShadowOff();
  t->SetLineSpacing(1.2);
  t->SetColor(0.62, 0.05, 0.45);
  t->SetJustificationToCentered();
  t->SetVerticalJustificationToTop();
  banner_->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  banner_->SetPosition(0.5, 0.97);
  banner_->VisibilityOff();
  renderer_->AddViewProp(banner_);
}

SpiralLayer::~SpiralLayer() = default;

bool SpiralLayer::channelAvailable(SpiralChannel c) const
{
  const SpiralChannelInfo info = spiralChannelInfo(c);
  return hasTrajectory() && (hasSpeeds_ || !info.needsProcess) && (hasKinematics_ || !info.needsKinematics) &&
         (hasThermal_ || !info.needsThermal);
}

void SpiralLayer::setTrajectory(const Trajectory* path, bool hasSpeeds, std::optional<PlanWindow> window,
                                const Transform& T_world_part)
{
  window_ = window;
  hasSpeeds_ = hasSpeeds && path;
  revolution_.clear();
  subPath_.clear();
  abscissa_.clear();
  violations_.clear();
  kinematicFlags_.clear();
  hasKinematics_ = false;
  hasThermal_ = false;
  pointCount_ = path ? static_cast<long long>(path->size()) : 0;
  const vtkIdType n = pointCount_;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  auto height = channelArray("height", n), ts = channelArray("travel_speed", n),
       wfs = channelArray("wire_feed", n), rev = channelArray("revolution", n);
  const double toMetresPerMinute = 1.0 / toInternalFactor("m/min");
  revolution_.resize(static_cast<size_t>(n));
  subPath_.resize(static_cast<size_t>(n));
  abscissa_.resize(static_cast<size_t>(n));
  revolutions_ = 0;
  double s = 0.0;
  for (vtkIdType i = 0; i < n; ++i) {
    const TrajectoryPoint& p = path->points[static_cast<size_t>(i)];
    const Vec3 w = T_world_part * p.position;
    points->SetPoint(i, w.x(), w.y(), w.z());
    if (i > 0) s += (p.position - path->points[static_cast<size_t>(i - 1)].position).norm();
    abscissa_[static_cast<size_t>(i)] = s;
    height->SetValue(i, p.height);
    ts->SetValue(i, p.travelSpeed);
    wfs->SetValue(i, p.wireFeed * toMetresPerMinute);
    rev->SetValue(i, p.revolution);
    revolution_[static_cast<size_t>(i)] = p.revolution;
    subPath_[static_cast<size_t>(i)] = p.path;
    revolutions_ = std::max(revolutions_, p.revolution + 1);
    if (window_ && window_->outside(p.height)) violations_.push_back(i);
  }
  path_->Initialize();
  path_->SetPoints(points);
  for (vtkDoubleArray* a : {height.Get(), ts.Get(), wfs.Get(), rev.Get()}) path_->GetPointData()->AddArray(a);
  tubeRadius_ = window_ && window_->h > 0.0 ? 0.35 * window_->h : 0.7;
  tubeFilter_->SetRadius(tubeRadius_);
  limit_ = std::max(0, revolutions_ - 1);
  endsOnAPoint_ =
      revolutions_ > 1 && std::count(revolution_.begin(), revolution_.end(), revolutions_ - 1) == 1;
  if (!channelAvailable(channel_)) channel_ = SpiralChannel::Height;
  rebuildCells();
  updateColours();
  updateVisibility();
}

bool SpiralLayer::setChannel(SpiralChannel c)
{
  if (!channelAvailable(c)) return false;
  channel_ = c;
  updateColours();
  return true;
}

void SpiralLayer::setVisible(bool on)
{
  visible_ = on;
  updateVisibility();
}

void SpiralLayer::setTube(bool on)
{
  tube_ = on;
  if (tube_) {
    mapper_->SetInputConnection(tubeFilter_->GetOutputPort());
  } else {
    mapper_->SetInputData(shown_);
  }
}

void SpiralLayer::setRevolutionLimit(int last)
{
  limit_ = std::clamp(last, 0, std::max(0, revolutions_ - 1));
  rebuildCells();
}

double SpiralLayer::shownLength() const
{
  return shownLast_ >= 0 ? abscissa_[static_cast<size_t>(shownLast_)] : 0.0;
}

void SpiralLayer::rebuildCells()
{
  // The build up to revolution `limit_`: in each sub-path (a multi-branch part has one per
  // branch, each counting its revolutions from 0) the points of those revolutions, drawn as one
  // polyline per run of consecutive points, so no segment jumps from one branch to the next.
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  long long count = 0, last = -1;
  offsets->InsertNextValue(0);
  auto closeRun = [&] {
    const vtkIdType open = offsets->GetValue(offsets->GetNumberOfValues() - 1);
    const vtkIdType size = connectivity->GetNumberOfValues() - open;
    if (size >= 2) {
      offsets->InsertNextValue(connectivity->GetNumberOfValues());
    } else if (size == 1) {
      connectivity->SetNumberOfValues(open);  // a lone point draws no line
    }
  };
  for (long long i = 0; i < pointCount_; ++i) {
    const auto k = static_cast<size_t>(i);
    if (revolution_[k] > limit_) continue;
    if (last < 0 || last != i - 1 || subPath_[k] != subPath_[static_cast<size_t>(last)]) closeRun();
    connectivity->InsertNextValue(i);
    last = i;
    ++count;
  }
  closeRun();
  shownPoints_ = count;
  shownLast_ = last;
  vtkNew<vtkCellArray> lines;
  lines->SetData(offsets, connectivity);
  shown_->Initialize();
  shown_->SetPoints(path_->GetPoints());
  shown_->GetPointData()->ShallowCopy(path_->GetPointData());
  shown_->SetLines(lines);

  vtkNew<vtkPoints> bad;
  vtkNew<vtkCellArray> verts;
  for (long long i : violations_) {
    if (revolution_[static_cast<size_t>(i)] > limit_) continue;
    double p[3];
    path_->GetPoint(i, p);
    const vtkIdType id = bad->InsertNextPoint(p);
    verts->InsertNextCell(1, &id);
  }
  shownViolations_ = bad->GetNumberOfPoints();
  vtkNew<vtkPoints> flagged;
  vtkNew<vtkCellArray> flaggedVerts;
  for (long long i : kinematicFlags_) {
    if (revolution_[static_cast<size_t>(i)] > limit_) continue;
    double p[3];
    path_->GetPoint(i, p);
    const vtkIdType id = flagged->InsertNextPoint(p);
    flaggedVerts->InsertNextCell(1, &id);
  }
  kinematicFlagPoints_->Initialize();
  kinematicFlagPoints_->SetPoints(flagged);
  kinematicFlagPoints_->SetVerts(flaggedVerts);
  violationPoints_->Initialize();
  violationPoints_->SetPoints(bad);
  violationPoints_->SetVerts(verts);
  updateVisibility();
}

void SpiralLayer::updateColours()
{
  if (!hasTrajectory()) return;
  const SpiralChannelInfo info = spiralChannelInfo(channel_);
  auto* values = vtkDoubleArray::SafeDownCast(path_->GetPointData()->GetArray(info.array));
  double r[2] = {0.0, 1.0};
  values->GetRange(r);
  ColorMap map = ColorMap::Plasma;
  const bool window = channel_ == SpiralChannel::Height && window_ && window_->hMax > window_->hMin;
  if (channel_ == SpiralChannel::Height) {
    map = ColorMap::Window;
    // The process window (with its tolerance) is the scale: blue thin, green nominal, red thick;
    // deposits outside it take the violation colour.
    if (window) r[0] = window_->hMin - window_->tolerance, r[1] = window_->hMax + window_->tolerance;
  } else if (channel_ == SpiralChannel::Revolution || channel_ == SpiralChannel::Dexterity ||
             channel_ == SpiralChannel::LimitMargin) {
    map = ColorMap::Viridis;  // dark where the robot is close to a singularity or a limit
  } else if (channel_ == SpiralChannel::CollapseRisk) {
    map = ColorMap::Risk;
    r[0] = 0.0, r[1] = 1.0;
  } else if (info.needsThermal) {
    map = ColorMap::Inferno;
    // The node under the point source peaks far above melting at a few points: the scale spans
    // the 2nd to 98th percentile so that those few do not leave the rest in one colour.
    if (channel_ == SpiralChannel::PeakTemperature && peakScale_.second > peakScale_.first)
      r[0] = peakScale_.first, r[1] = peakScale_.second;
    // The interpass limit, when set, sits inside the scale so that the colours above it read as too hot.
    if (channel_ == SpiralChannel::InterpassTemperature && interpassLimitC_ > 0.0)
      r[1] = std::max(r[1], interpassLimitC_);
  }
  if (!(r[1] > r[0])) {
    // A constant channel (the wire feed in synergic mode) still gets a readable legend.
    const double pad = std::max(1e-3, 0.05 * std::abs(r[0]));
    r[0] -= pad, r[1] += pad;
  }
  range_ = {r[0], r[1]};
  vtkSmartPointer<vtkLookupTable> lut = makeLookupTable(map, r[0], r[1]);
  if (window) {
    lut->SetBelowRangeColor(kOutsideColour[0], kOutsideColour[1], kOutsideColour[2], 1.0);
    lut->SetAboveRangeColor(kOutsideColour[0], kOutsideColour[1], kOutsideColour[2], 1.0);
    lut->UseBelowRangeColorOn();
    lut->UseAboveRangeColorOn();
    const double h = window_->h > 0.0 ? window_->h : 0.5 * (window_->hMin + window_->hMax);
    legend_.setLabels(
        {window_->hMin, 0.5 * (window_->hMin + h), h, 0.5 * (h + window_->hMax), window_->hMax});
  } else {
    legend_.setLabels({});
  }
  mapper_->SelectColorArray(info.array);
  mapper_->SetLookupTable(lut);
  mapper_->SetScalarRange(r);
  mapper_->ScalarVisibilityOn();
  legend_.setLookupTable(lut);
  if (channel_ == SpiralChannel::CollapseRisk) legend_.setLabels({0.0, 1.0});
  // The limit is one of the labels, so the colour where the deposit gets too hot reads off the bar.
  if (channel_ == SpiralChannel::InterpassTemperature && interpassLimitC_ > r[0] && interpassLimitC_ < r[1])
    legend_.setLabels({r[0], interpassLimitC_, 0.5 * (interpassLimitC_ + r[1]), r[1]});
  legend_.setLabelFormat(channel_ == SpiralChannel::Revolution || channel_ == SpiralChannel::CollapseRisk
                             ? QStringLiteral("%.0f")
                             : labelFormatFor(r[0], r[1]));
  QString title = info.unit.isEmpty() ? info.name : QStringLiteral("%1 (%2)").arg(info.name, info.unit);
  title += thermalLegendNote();
  if (window) title += QObject::tr("\nmagenta: outside the window");
  if (hasKinematics_ && !kinematicFlags_.empty()) title += QObject::tr("\nred: unreachable or colliding");
  legend_.setTitle(title);
}

QString SpiralLayer::thermalLegendNote() const
{
  const QLocale loc;
  switch (channel_) {
    case SpiralChannel::PeakTemperature:
      return QObject::tr("\nmelts at %1 °C; 2 %-98 % of points").arg(loc.toString(meltingC_, 'f', 0));
    case SpiralChannel::InterpassTemperature:
      return interpassLimitC_ > 0.0 ? QObject::tr("\nlimit %1 °C").arg(loc.toString(interpassLimitC_, 'f', 0))
                                    : QString();
    case SpiralChannel::CollapseRisk:
      return QObject::tr("\n1: at risk (%1 points), 0: safe").arg(loc.toString(riskPoints_));
    default:
      return QString();
  }
}

void SpiralLayer::setHiddenByPart(bool hidden)
{
  hiddenByPart_ = hidden;
  updateVisibility();
}

void SpiralLayer::updateVisibility()
{
  const bool on = visible_ && !hiddenByPart_ && hasTrajectory();
  actor_->SetVisibility(on);
  legend_.setVisible(on);
  violationActor_->SetVisibility(on && shownViolations_ > 0);
  kinematicFlagActor_->SetVisibility(on && kinematicFlagPoints_->GetNumberOfPoints() > 0);
  banner_->SetVisibility(on && !violations_.empty());
  if (!violations_.empty() && window_) {
    const QString text = QObject::tr("Infeasible plan\n%1 point(s) outside the window %2 to %3 mm")
                             .arg(violations_.size())
                             .arg(window_->hMin, 0, 'f', 2)
                             .arg(window_->hMax, 0, 'f', 2);
    banner_->SetInput(text.toUtf8().constData());
  }
}

}  // namespace spira::ui

namespace spira::ui {

void SpiralLayer::setKinematics(const KinematicsResult* k)
{
  kinematicFlags_.clear();
  hasKinematics_ = k && hasTrajectory() && static_cast<long long>(k->size()) == pointCount_ &&
                   k->checks.size() == k->size();
  const vtkIdType n = hasKinematics_ ? pointCount_ : 0;
  path_->GetPointData()->RemoveArray("dexterity");
  path_->GetPointData()->RemoveArray("limit_margin");
  if (hasKinematics_) {
    auto dexterity = channelArray("dexterity", n), margin = channelArray("limit_margin", n);
    for (vtkIdType i = 0; i < n; ++i) {
      const KinematicsCheck& c = k->checks[static_cast<size_t>(i)];
      dexterity->SetValue(i, c.dexterity);
      margin->SetValue(i, c.limitMarginDeg);
      if (!c.reachable || c.collision) kinematicFlags_.push_back(i);
    }
    path_->GetPointData()->AddArray(dexterity);
    path_->GetPointData()->AddArray(margin);
  }
  if (!channelAvailable(channel_)) channel_ = SpiralChannel::Height;
  if (!hasTrajectory()) return;
  rebuildCells();
  updateColours();
  updateVisibility();
}

}  // namespace spira::ui
