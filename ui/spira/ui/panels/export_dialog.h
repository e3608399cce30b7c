#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <string>

#include <QDialog>
#include <QStringList>

#include "spira/plugin/parameter.h"
#include "spira/ui/jobs/export_request.h"

class QComboBox;
class QLabel;
class QLineEdit;
class QPlainTextEdit;
class QPushButton;
class QStackedWidget;
class QTabWidget;
class QTimer;
class QToolButton;

namespace spira {
class Document;
class PluginRegistry;
}  // namespace spira

namespace spira::ui {

class LogPanel;
class ParamPanel;
class TaskRunner;
struct TaskOutcome;

// File > Export Robot Program: the program format (one page per exporter plugin, its parameters
// generated from its schema), the path preparation, the output folder, a preview of the first
// lines of every file the export would write and the warnings about the plan, all before anything
// is written. The preview is a real export into a temporary folder, run on a worker thread each
// time a setting changes; Export writes the same files into the output folder (all or none) and
// reports them in the messages panel. The exporter's values are stored in the document's plan
// settings (one undo step) when the program is written.
class ExportDialog : public QDialog {
  Q_OBJECT

 public:
  static constexpr int kPreviewLines = 40;

  ExportDialog(Document& doc, const PluginRegistry& registry, LogPanel* log, QWidget* parent = nullptr);
  ~ExportDialog() override;

  // The plan or the settings changed: the preview follows.
  void refresh();
  void setExporter(const std::string& id);
  std::string exporterId() const;
  void setOutputFolder(const QString& dir);
  QString outputFolder() const;
  // Sets one value of the current exporter's parameters (as the user would in its panel).
  void setExporterValue(const std::string& key, const ParamValue& value);

  bool previewBusy() const;
  // Whether the last preview ran (false: no plan, or the export would fail; the summary says why).
  bool previewOk() const { return previewOk_; }
  // Writes the program (on the worker thread); exported() reports the outcome.
  void exportProgram();

  QComboBox* formatCombo() const { return format_; }
  ParamPanel* exporterPanel(const std::string& id) const;
  ParamPanel* prepPanel() const { return prepPanel_; }
  QTabWidget* previewTabs() const { return previewTabs_; }
  QLabel* warningsLabel() const { return warnings_; }
  QLabel* summaryLabel() const { return summary_; }
  QPushButton* exportButton() const { return exportButton_; }
  // The warnings of the last preview, one per entry.
  const QStringList& warnings() const { return warningList_; }

 signals:
  void previewUpdated(bool ok);
  void exported(bool ok, const QStringList& files);

 private:
  // Construction stages: the settings (format, folder, exporter and preparation panels), the
  // preview (warnings, summary, files), the splitter with the buttons, the controls' wiring.
  QWidget* buildSettingsSide(QToolButton*& browse);
  QTabWidget* buildSettingTabs(QWidget* settings);
  void connectSettingsPanel(ParamPanel* panel);
  QWidget* buildPreviewSide();
  void layOut(QWidget* settings, QWidget* preview);
  void connectControls(QToolButton* browse);
  void schedulePreview();
  void startPreview();
  void finishPreview(const TaskOutcome& outcome, const std::shared_ptr<ExportPreview>& preview);
  void finishExport(const TaskOutcome& outcome, const std::shared_ptr<ExportOutcome>& result,
                    const QString& dir, const std::string& exporterId, const ParamSet& params);
  void showWarnings(const ExportPreview* preview);
  void browse();
  ExportRequest request() const;
  void refreshExportButton();
  void showEvent(QShowEvent* event) override;

  Document& doc_;
  std::uint64_t subscription_ = 0;
  const PluginRegistry& registry_;
  LogPanel* log_;
  TaskRunner* tasks_ = nullptr;
  QTimer* debounce_ = nullptr;
  QComboBox* format_ = nullptr;
  QLabel* formatText_ = nullptr;
  QLineEdit* folder_ = nullptr;
  QStackedWidget* exporterPages_ = nullptr;
  std::map<std::string, ParamPanel*> exporterPanels_;
  std::map<std::string, ParamSet> values_;  // by section: exporter ids and "prep"
  ParamPanel* prepPanel_ = nullptr;
  QLabel* warnings_ = nullptr;
  QLabel* summary_ = nullptr;
  QTabWidget* previewTabs_ = nullptr;
  QPushButton* exportButton_ = nullptr;
  QStringList warningList_;
  bool previewPending_ = false;
  bool previewOk_ = false;
  bool exporting_ = false;
};

}  // namespace spira::ui
