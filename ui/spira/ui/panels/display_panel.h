#pragma once

#include <QDockWidget>

class QAction;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QFormLayout;
class QGroupBox;
class QLabel;
class QSlider;
class QSpinBox;
class QToolButton;
class QVBoxLayout;

namespace spira::ui {

class ProcessChart;
class SceneView;
enum class PartStyle;
enum class SpiralChannel;

// The "Display" dock: how the plan is drawn. Part style (plain, coloured by the field,
// transparent, hidden), the field's colour range and iso-lines, generatrices and closure point,
// the spiral's colour channel and tube, and a slider that shows the build up to a revolution.
// These are view settings, not document state: they drive the SceneView and the chart directly.
class DisplayPanel : public QDockWidget {
  Q_OBJECT

 public:
  // `chartToggle` shows and hides the chart's dock.
  DisplayPanel(SceneView* view, ProcessChart* chart, QAction* chartToggle, QWidget* parent = nullptr);

  // The view was given new results: ranges, channels and the slider follow them.
  void resultsChanged();

  void setPartStyle(PartStyle style);
  // Returns false when the channel is not available (no process channels yet).
  bool setChannel(SpiralChannel channel);
  void setRevolutionLimit(int last);
  void setTube(bool on);
  void setGeneratricesVisible(bool on);
  void setFieldRange(double lo, double hi);

  QComboBox* partStyleCombo() const { return partStyle_; }
  QComboBox* channelCombo() const { return channel_; }
  QSlider* revolutionSlider() const { return revolution_; }
  QLabel* revolutionLabel() const { return revolutionText_; }
  QCheckBox* spiralCheck() const { return spiral_; }
  QCheckBox* tubeCheck() const { return tube_; }
  QCheckBox* framesCheck() const { return frames_; }
  QCheckBox* generatricesCheck() const { return generatrices_; }
  QDoubleSpinBox* fieldMin() const { return fieldMin_; }
  QDoubleSpinBox* fieldMax() const { return fieldMax_; }
  QSpinBox* isoLines() const { return isoLines_; }

 signals:
  // The shown build now ends at arc length `s` (mm) along the path.
  void buildCutChanged(double s);
  // The user asked for the torch frames to be drawn (or hidden).
  void framesToggled(bool on);

 private:
  // Construction stages, top to bottom of the dock, then the controls' wiring.
  QFormLayout* buildPartRow(QWidget* body);
  QGroupBox* buildFieldBox(QWidget* body);
  QGroupBox* buildPathsBox(QWidget* body);
  QGroupBox* buildSpiralBox(QWidget* body);
  void finishLayout(QWidget* body, QVBoxLayout* layout, QAction* chartToggle);
  void connectControls();
  void applyFieldRange();
  void refreshRevolutionText();
  void render();

  SceneView* view_;
  ProcessChart* chart_;
  QComboBox* partStyle_ = nullptr;
  QGroupBox* fieldBox_ = nullptr;
  QDoubleSpinBox* fieldMin_ = nullptr;
  QDoubleSpinBox* fieldMax_ = nullptr;
  QToolButton* fieldAuto_ = nullptr;
  QSpinBox* isoLines_ = nullptr;
  QCheckBox* generatrices_ = nullptr;
  QCheckBox* closure_ = nullptr;
  QCheckBox* guide_ = nullptr;
  QCheckBox* scan_ = nullptr;
  QGroupBox* spiralBox_ = nullptr;
  QCheckBox* spiral_ = nullptr;
  QComboBox* channel_ = nullptr;
  QCheckBox* tube_ = nullptr;
  QCheckBox* frames_ = nullptr;
  QSlider* revolution_ = nullptr;
  QLabel* revolutionText_ = nullptr;
  bool updating_ = false;
};

}  // namespace spira::ui
