#pragma once

#include <array>
#include <memory>

#include <QImage>
#include <QWidget>

#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include "spira/planning/strategy_compare.h"

class QComboBox;
class QLabel;
class QPushButton;
class QVTKOpenGLNativeWidget;
class vtkActor;
class vtkCallbackCommand;
class vtkCamera;
class vtkGenericOpenGLRenderWindow;
class vtkLookupTable;
class vtkObject;
class vtkPolyData;
class vtkPolyDataMapper;
class vtkRenderer;

namespace spira {
class Document;
class PluginRegistry;
}  // namespace spira

namespace spira::ui {

class ColorLegend;
class TaskRunner;
struct TaskOutcome;

// Two planning strategies side by side: each one's deposit-height map on the part (the CTPP path,
// or the planar baseline's layer contours) in its own 3D view, both on the same colour scale (the
// process window, with its legend) and with one camera, so that turning one turns the other. The
// comparison comes from running every strategy on the document's part in the background (what
// `spira-cli compare` does) or from the compare.csv/compare.json that command wrote.
class CompareView : public QWidget {
  Q_OBJECT

 public:
  static constexpr int kSides = 2;

  CompareView(Document& doc, const PluginRegistry& registry, QWidget* parent = nullptr);
  ~CompareView() override;

  // Runs the comparison on the document's part (worker thread); comparisonReady() reports it.
  void runOnPart();
  void cancel();
  bool busy() const;
  // Reads compare.csv/compare.json (a file of the pair or their folder). Returns false, with the
  // reason in the status line, when they cannot be read.
  bool openFile(const QString& path);
  void setComparison(Comparison comparison);
  const Comparison& comparison() const { return comparison_; }

  // Shows strategy `index` (into comparison().strategies) on `side` (0 left, 1 right).
  void setStrategy(int side, int index);
  int strategy(int side) const;
  QComboBox* strategyCombo(int side) const { return pickers_.at(static_cast<size_t>(side)); }
  QLabel* summaryLabel(int side) const { return summaries_.at(static_cast<size_t>(side)); }
  QLabel* statusLabel() const { return status_; }
  vtkRenderer* renderer(int side) const;
  vtkPolyData* polyData(int side) const;
  vtkLookupTable* lookupTable() const;
  // The colour scale's range (mm): the process window with its tolerance.
  std::pair<double, double> colourRange() const { return range_; }
  ColorLegend& legend() const { return *legend_; }
  QImage grabViews();

 signals:
  void comparisonReady(bool ok);

 private:
  void showSide(int side);
  void fitCamera();
  void renderAll();
  void finishRun(const TaskOutcome& outcome, const std::shared_ptr<Comparison>& result);
  static void onInteraction(vtkObject* caller, unsigned long eventId, void* clientData, void* callData);

  Document& doc_;
  const PluginRegistry& registry_;
  TaskRunner* tasks_ = nullptr;
  Comparison comparison_;
  QLabel* status_ = nullptr;
  QPushButton* run_ = nullptr;
  QPushButton* open_ = nullptr;
  QPushButton* cancel_ = nullptr;
  std::array<QComboBox*, kSides> pickers_{};
  std::array<QLabel*, kSides> summaries_{};
  std::array<QVTKOpenGLNativeWidget*, kSides> widgets_{};
  std::array<vtkNew<vtkGenericOpenGLRenderWindow>, kSides> windows_;
  std::array<vtkNew<vtkRenderer>, kSides> renderers_;
  std::array<vtkNew<vtkPolyData>, kSides> data_;
  std::array<vtkNew<vtkPolyDataMapper>, kSides> mappers_;
  std::array<vtkNew<vtkActor>, kSides> actors_;
  vtkNew<vtkCamera> camera_;
  vtkNew<vtkCallbackCommand> linker_;
  vtkSmartPointer<vtkLookupTable> lut_;
  std::unique_ptr<ColorLegend> legend_;
  std::pair<double, double> range_{0.0, 1.0};
  bool updating_ = false;
};

}  // namespace spira::ui
