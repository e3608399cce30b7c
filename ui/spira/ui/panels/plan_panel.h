#pragma once

#include <map>
#include <string>

#include <QDockWidget>

#include "spira/document/document.h"

class QAction;
class QComboBox;
class QLabel;
class QStackedWidget;
class QTabWidget;
class QToolButton;
class QVBoxLayout;

namespace spira {
class PluginRegistry;
}

namespace spira::ui {

class ParamPanel;
class StageProgress;

// The "Plan" dock: the plan settings as panels generated from the schemas (spiral, process, and
// the chosen decomposer's and closure finder's), the strategy choice, the Plan button, the
// progress of a running plan and the verdict on the last one.
//
// It shows the Document and edits it only through its API: every edit is one undo step, and the
// panels follow every change of the settings (undo, redo, opening a project) through the
// Document's notifications.
class PlanPanel : public QDockWidget {
  Q_OBJECT

 public:
  PlanPanel(Document& doc, const PluginRegistry& registry, QWidget* parent = nullptr);
  ~PlanPanel() override;

  // The action the Plan button triggers.
  void setPlanAction(QAction* plan);

  // The panel of a settings section: "spiral", "process" or the chosen plugins' ids.
  ParamPanel* panel(const std::string& section) const;
  QComboBox* decomposerCombo() const { return decomposer_; }
  QComboBox* closureFinderCombo() const { return closure_; }
  QTabWidget* tabs() const { return tabs_; }
  StageProgress* progress() const { return progress_; }
  QToolButton* planButton() const { return planButton_; }
  // The verdict on the plan in the document ("Feasible plan: ..." / "Infeasible plan: ...").
  QLabel* verdictLabel() const { return verdict_; }

 private:
  void onDocumentChanged(const ChangeSet& changes);
  void connectPanel(ParamPanel* panel);
  void rebuildStrategyPanels();
  void refreshValues();
  void refreshVerdict();
  QString labelOf(const std::string& section, const std::string& key) const;

  Document& doc_;
  const PluginRegistry& registry_;
  Document::SubscriptionId subscription_ = 0;
  QTabWidget* tabs_ = nullptr;
  QComboBox* decomposer_ = nullptr;
  QComboBox* closure_ = nullptr;
  QLabel* decomposerText_ = nullptr;
  QLabel* closureText_ = nullptr;
  QVBoxLayout* decomposerBox_ = nullptr;
  QVBoxLayout* closureBox_ = nullptr;
  std::map<std::string, ParamPanel*> panels_;
  std::string shownDecomposer_, shownClosure_;
  QToolButton* planButton_ = nullptr;
  StageProgress* progress_ = nullptr;
  QLabel* verdict_ = nullptr;
  QStackedWidget* status_ = nullptr;
};

}  // namespace spira::ui
