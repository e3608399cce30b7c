#pragma once

#include <optional>
#include <vector>

#include <vtkNew.h>
#include <QObject>
#include <QPoint>

#include "spira/base/transform.h"

class vtkActor;
class vtkCellPicker;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkUnsignedCharArray;
class QVTKOpenGLNativeWidget;

namespace spira::ui {

class SceneView;

// Places clicked in the 3D view, alternately on the part's surface and on a scan's points: the pairs
// that start an alignment where the fit alone cannot (a scan in its scanner's frame, far off the part).
// While active, a click that is not a drag picks (a drag still turns the view); each pick is marked,
// blue on the part and orange on the scan.
class PairPicker : public QObject {
  Q_OBJECT

 public:
  enum class Expect { Part, Scan };

  explicit PairPicker(SceneView& view, QObject* parent = nullptr);
  ~PairPicker() override;

  void start(vtkActor* part, vtkActor* scan);
  void stop();
  bool active() const { return active_; }
  Expect expecting() const { return partPoints_.size() > scanPoints_.size() ? Expect::Scan : Expect::Part; }
  // Complete pairs so far.
  int pairCount() const { return int(scanPoints_.size()); }
  // World coordinates of the picks, in order.
  const std::vector<Vec3>& partPoints() const { return partPoints_; }
  const std::vector<Vec3>& scanPoints() const { return scanPoints_; }

  // Picks at a position of the view widget (its logical pixels); false when it hits nothing expected.
  bool pickAt(const QPoint& pos);
  // Where a world point shows in the view widget, for tests and tours.
  QPoint viewPositionOf(const Vec3& world) const;

 signals:
  void picked();
  void missed();

 protected:
  bool eventFilter(QObject* watched, QEvent* event) override;

 private:
  void updateMarkers();
  std::optional<Vec3> frontScanPointAt(double x, double y) const;

  SceneView& view_;
  QVTKOpenGLNativeWidget* widget_ = nullptr;
  vtkNew<vtkCellPicker> partPicker_;
  vtkActor* scan_ = nullptr;
  vtkNew<vtkPolyData> markers_;
  vtkNew<vtkPolyDataMapper> mapper_;
  vtkNew<vtkActor> actor_;
  std::vector<Vec3> partPoints_, scanPoints_;
  bool active_ = false;
  QPoint press_;
};

}  // namespace spira::ui
