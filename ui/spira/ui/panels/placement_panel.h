#pragma once

#include <array>
#include <memory>

#include <QDockWidget>

#include "spira/base/transform.h"
#include "spira/document/document.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QPushButton;

namespace spira {
struct TriangleMesh;
}

namespace spira::ui {

// The part's placement as the panel edits it: a translation (mm) and rotations about the fixed
// world axes X, then Y, then Z (degrees), so R = Rz * Ry * Rx.
struct Placement {
  Vec3 translation = Vec3::Zero();
  Vec3 rotationDeg = Vec3::Zero();

  Transform toTransform() const;
  // The angles are chosen in (-180, 180], Y in [-90, 90].
  static Placement fromTransform(const Transform& T);
};

// `T` moved along world Z so that the lowest vertex of `mesh` (part frame) lands on the plane
// z = `planeZ`.
Transform droppedOnPlane(const TriangleMesh& mesh, const Transform& T, double planeZ);

// The "Placement" dock: where the part sits on the substrate. Edits go through the Document
// (setPartPlacement, setLowerBoundaryOverride), one undo step each; a spin box held down or
// scrolled merges into one step. The panel follows the document through its notifications.
class PlacementPanel : public QDockWidget {
  Q_OBJECT

 public:
  explicit PlacementPanel(Document& doc, QWidget* parent = nullptr);
  ~PlacementPanel() override;

  // x, y, z translation (mm) then rotation about x, y, z (deg).
  QDoubleSpinBox* field(int index) const { return fields_[static_cast<size_t>(index)]; }
  QPushButton* dropButton() const { return drop_; }
  QPushButton* levelBaseButton() const { return level_; }
  QPushButton* resetButton() const { return reset_; }
  // Item 0 is "Automatic (lowest)", item i + 1 the part's boundary loop i.
  QComboBox* lowerBoundaryCombo() const { return lower_; }

  // Moves the part down (or up) onto the substrate plane; false when there is no part or the
  // substrate is not a plane.
  bool dropToSubstrate();
  // Cuts the part level through the highest point of its base edge (a scan cut at a slant, see
  // level_base.h) and drops it onto the substrate plane, one undo step; false (with failed()
  // emitted when the cut itself fails) when there is no part or the substrate is not a plane.
  bool levelBase();

  // Builds the part on a pipe of `radius` mm about the x, y or z `axis` through the origin (one undo step).
  void useCylinderSubstrate(double radius, char axis);
  // Builds the part on the plate again, at the height it had (one undo step).
  void usePlateSubstrate();

 signals:
  void failed(const QString& message, const QString& hint);
  // The user asked for a substrate mesh file: the window imports it.
  void substrateMeshRequested();

 private:
  void onDocumentChanged(const ChangeSet& changes);
  void refresh();
  void refreshLoops();
  void applyFields(int changed);

  Document& doc_;
  Document::SubscriptionId subscription_ = 0;
  std::array<QDoubleSpinBox*, 6> fields_{};
  QPushButton* drop_ = nullptr;
  QLabel* substrate_ = nullptr;
  double lastPlateZ_ = 0.0;
  QPushButton* level_ = nullptr;
  QPushButton* reset_ = nullptr;
  QComboBox* lower_ = nullptr;
  QLabel* note_ = nullptr;
  std::shared_ptr<const TriangleMesh> loopsMesh_;
  bool updating_ = false;
};

}  // namespace spira::ui
