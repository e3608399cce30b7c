#pragma once

#include <QByteArray>
#include <QObject>
#include <QPointer>

#include "spira/ui/window/window_parts.h"

class QAction;
class QActionGroup;

namespace spira::ui {

class Autosave;
class GuidedTour;
class InteractiveQuality;
class PlacementPanel;
class PresetBar;
struct TaskOutcome;

// The main window's comfort features, installed once by the window: the Placement dock, the
// preset row above the plan settings, View > Theme, Help > Keyboard Shortcuts and Guided
// Sample, fast frames while the 3D view moves (InteractiveQuality), and (in a user session)
// autosave with the offer to recover after a crash.
// A child of the window, which keeps it (MainWindow::comfortFeatures()).
class ComfortFeatures : public QObject {
  Q_OBJECT

 public:
  // `userSession`: a real session (the window persists its layout): autosave runs and the
  // saved theme is applied. `interactive`: prompts (recovery offer, preset names) may be shown.
  ComfortFeatures(const WindowParts& parts, bool userSession, bool interactive);
  ~ComfortFeatures() override;

  PlacementPanel* placementPanel() const { return placement_; }
  PresetBar* presetBar() const { return presets_; }
  QActionGroup* themeActions() const { return themes_; }
  QAction* shortcutsAction() const { return shortcuts_; }
  QAction* tourAction() const { return tour_; }
  // The guided sample's window (created on first use).
  GuidedTour* guidedTour();
  // Null outside a user session.
  Autosave* autosave() const { return autosave_; }
  // Fast frames of the 3D view while it moves or a job runs.
  InteractiveQuality* interactiveQuality() const { return quality_; }

  // The user session: offer the previous session's autosaved work (a question when
  // interactive, restored without asking when `restoreWithoutAsking`).
  void offerRecovery(bool restoreWithoutAsking = false);
  // Re-colours what the palette does not reach (the 3D view's background) after a theme change.
  void themeChanged();
  // The window's outcomes, passed on to the guided sample when it is open.
  void fileOpened(const QString& path, bool ok);
  void planFinished(const TaskOutcome& outcome);

 private:
  WindowParts parts_;
  bool interactive_;
  InteractiveQuality* quality_ = nullptr;
  PlacementPanel* placement_ = nullptr;
  PresetBar* presets_ = nullptr;
  QActionGroup* themes_ = nullptr;
  QAction* shortcuts_ = nullptr;
  QAction* tour_ = nullptr;
  QPointer<GuidedTour> guide_;
  Autosave* autosave_ = nullptr;
  QByteArray layoutBeforeTheme_;
};

}  // namespace spira::ui
