// The Plan dock's parameter panels: generated from the schemas (groups, ranges, units, choices,
// tooltips), edited through the Document (one undo step per edit, undo/redo shown back), reset
// per field and per section, and following the Document when it changes elsewhere.
#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QToolButton>

#include <gtest/gtest.h>

#include "builtin_plugins.h"
#include "spira/document/document.h"
#include "spira/pipeline/thermal_schema.h"
#include "spira/planning/plan_schemas.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/ui/panels/param_field.h"
#include "spira/ui/panels/param_panel.h"
#include "spira/ui/panels/plan_panel.h"
#include "spira/ui/window/main_window.h"
#include "support/gui_test_support.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

using spira::ui::MainWindow;
using spira::ui::MainWindowOptions;
using spira::ui::ParamField;
using spira::ui::ParamPanel;

class PlanSettingsPanel : public ::testing::Test {
 protected:
  void SetUp() override
  {
    window_ = std::make_unique<MainWindow>(doc_, builtinRegistry(), MainWindowOptions{false, false});
    showAndWait(*window_);
    panel_ = window_->planPanel();
  }
  ParamPanel* section(const std::string& name) const { return panel_->panel(name); }
  double storedDouble(const std::string& s, const std::string& key) const
  {
    return doc_.settings()
        ->section(s)
        .withDefaults(s == "spiral" ? spiralSchema() : processSchema())
        .getDouble(key);
  }

  Document doc_;
  std::unique_ptr<MainWindow> window_;
  ui::PlanPanel* panel_ = nullptr;
};

TEST_F(PlanSettingsPanel, EveryParameterOfTheSchemasHasAnEditorOfItsKindInItsCategory)
{
  for (const auto& [name, schema] : {std::pair<std::string, const ParamSchema*>{"spiral", &spiralSchema()},
                                     {"process", &processSchema()},
                                     {"thermal", &thermalSchema()}}) {
    ParamPanel* p = section(name);
    ASSERT_NE(p, nullptr) << name;
    QStringList groups;
    for (QGroupBox* g : p->findChildren<QGroupBox*>()) groups << g->title();
    for (const ParamDef& d : schema->defs()) {
      ParamField* f = p->field(d.key);
      ASSERT_NE(f, nullptr) << d.key;
      EXPECT_TRUE(groups.contains(QString::fromStdString(d.category))) << d.key;
      auto* box = qobject_cast<QGroupBox*>(f->parentWidget());
      ASSERT_NE(box, nullptr);
      EXPECT_EQ(box->title(), QString::fromStdString(d.category)) << d.key;
      EXPECT_EQ(p->label(d.key)->text(), QString::fromStdString(d.label));
      EXPECT_EQ(f->editor()->toolTip(), QString::fromStdString(d.tooltip));
      EXPECT_TRUE(p->label(d.key)->toolTip().contains(QString::fromStdString(d.key)));
      switch (d.type) {
        case ParamType::Double: {
          auto* spin = qobject_cast<QDoubleSpinBox*>(f->editor());
          ASSERT_NE(spin, nullptr) << d.key;
          EXPECT_DOUBLE_EQ(spin->minimum(), *d.min) << d.key;
          EXPECT_DOUBLE_EQ(spin->maximum(), *d.max) << d.key;
          // A dimensionless number (the thermal stage's Bond threshold) has no suffix; degrees show as a
          // degree sign.
          const QString suffix = d.unit.empty()    ? QString()
                                 : d.unit == "deg" ? QStringLiteral("°")
                                                   : " " + QString::fromStdString(d.unit);
          EXPECT_EQ(spin->suffix(), suffix) << d.key;
          break;
        }
        case ParamType::Choice: {
          auto* combo = qobject_cast<QComboBox*>(f->editor());
          ASSERT_NE(combo, nullptr) << d.key;
          ASSERT_EQ(combo->count(), static_cast<int>(d.choices.size()));
          for (int i = 0; i < combo->count(); ++i)
            EXPECT_EQ(combo->itemText(i), QString::fromStdString(d.choices[static_cast<size_t>(i)]));
          EXPECT_EQ(combo->currentText(), QString::fromStdString(std::get<std::string>(d.defaultValue)));
          break;
        }
        case ParamType::Path:
          EXPECT_NE(qobject_cast<QLineEdit*>(f->editor()), nullptr) << d.key;
          ASSERT_NE(f->browseButton(), nullptr) << d.key;
          break;
        default:
          break;
      }
      EXPECT_FALSE(f->resetButton()->isEnabled()) << d.key;  // at its default
    }
  }
  // h: 0.05 .. 50 mm, shown as "2.00 mm"; "0 = automatic" fields read "auto" at 0.
  auto* h = qobject_cast<QDoubleSpinBox*>(section("spiral")->field("h")->editor());
  EXPECT_EQ(h->text(), "2.00 mm");
  EXPECT_EQ(qobject_cast<QDoubleSpinBox*>(section("spiral")->field("h_min")->editor())->text(), "auto");

  // The strategy tab: the registry's decomposers, and the chosen ones' own panels.
  QComboBox* decomposers = panel_->decomposerCombo();
  const auto registered = builtinRegistry().ofKind(PluginKind::Decomposer);
  ASSERT_EQ(decomposers->count(), static_cast<int>(registered.size()));
  EXPECT_EQ(decomposers->currentData().toString().toStdString(), doc_.settings()->decomposerId);
  ParamPanel* iso = section(doc_.settings()->decomposerId);
  ASSERT_NE(iso, nullptr);
  auto* points = qobject_cast<QSpinBox*>(iso->field("points_per_rev")->editor());
  ASSERT_NE(points, nullptr);
  EXPECT_EQ(points->minimum(), 8);
  EXPECT_EQ(points->maximum(), 20000);
  EXPECT_EQ(points->value(), 360);
  ParamPanel* closure = section(doc_.settings()->closureFinderId);
  ASSERT_NE(closure, nullptr);
  EXPECT_NE(qobject_cast<QCheckBox*>(closure->field("refine")->editor()), nullptr);
}

TEST_F(PlanSettingsPanel, EditsAreUndoStepsAndThePanelFollowsUndoRedo)
{
  auto* h = qobject_cast<QDoubleSpinBox*>(section("spiral")->field("h")->editor());
  h->setValue(2.5);  // what typing 2.5 and Enter does (no keyboard tracking)
  EXPECT_DOUBLE_EQ(storedDouble("spiral", "h"), 2.5);
  EXPECT_EQ(window_->actions().undo->text(), "&Undo Change Nominal deposit height");
  EXPECT_TRUE(section("spiral")->field("h")->resetButton()->isEnabled());
  EXPECT_TRUE(section("spiral")->label("h")->font().bold());
  EXPECT_TRUE(section("spiral")->resetAllButton()->isEnabled());

  auto* mode = qobject_cast<QComboBox*>(section("process")->field("process")->editor());
  mode->setCurrentIndex(mode->findText("constant-ts"));
  emit mode->activated(mode->currentIndex());  // what choosing an item with the mouse sends
  EXPECT_EQ(doc_.settings()->section("process").getString("process"), "constant-ts");
  EXPECT_EQ(window_->actions().undo->text(), "&Undo Change Process mode");

  window_->actions().undo->trigger();
  EXPECT_EQ(mode->currentText(), "synergic");
  EXPECT_DOUBLE_EQ(h->value(), 2.5);
  window_->actions().undo->trigger();
  EXPECT_DOUBLE_EQ(h->value(), 2.0);
  EXPECT_FALSE(section("spiral")->field("h")->resetButton()->isEnabled());
  EXPECT_FALSE(section("spiral")->label("h")->font().bold());
  window_->actions().redo->trigger();
  EXPECT_DOUBLE_EQ(h->value(), 2.5);
  EXPECT_DOUBLE_EQ(storedDouble("spiral", "h"), 2.5);
}

TEST_F(PlanSettingsPanel, ResetPerFieldAndPerSectionGoThroughTheDocument)
{
  doc_.setParam("process", "wfs", 3.1);
  doc_.setParam("process", "bead_width", 6.0);
  // An edit made elsewhere shows in the panel.
  auto* wfs = qobject_cast<QDoubleSpinBox*>(section("process")->field("wfs")->editor());
  EXPECT_DOUBLE_EQ(wfs->value(), 3.1);
  EXPECT_EQ(wfs->suffix(), " m/min");

  section("process")->field("wfs")->resetButton()->click();
  EXPECT_FALSE(doc_.settings()->section("process").has("wfs"));
  EXPECT_DOUBLE_EQ(wfs->value(), 2.3);
  EXPECT_TRUE(doc_.settings()->section("process").has("bead_width"));
  EXPECT_EQ(window_->actions().undo->text(), "&Undo Reset Wire-feed speed");

  section("process")->resetAllButton()->click();
  EXPECT_TRUE(doc_.settings()->section("process").values().empty());
  EXPECT_DOUBLE_EQ(qobject_cast<QDoubleSpinBox*>(section("process")->field("bead_width")->editor())->value(),
                   5.2);
  EXPECT_FALSE(section("process")->resetAllButton()->isEnabled());
  window_->actions().undo->trigger();
  EXPECT_DOUBLE_EQ(qobject_cast<QDoubleSpinBox*>(section("process")->field("bead_width")->editor())->value(),
                   6.0);

  // Screenshot of the process tab with changed values (bold labels, reset buttons).
  doc_.setParam("process", "ts_max", 40.0);
  panel_->tabs()->setCurrentIndex(1);
  const QImage image = window_->captureImage();
  EXPECT_GT(distinctColours(image, rectIn(*window_, panel_)), 30);
  saveDocScreenshot(image, "plan-parameters.png");
}

TEST_F(PlanSettingsPanel, ChoosingADecomposerShowsItsParametersAndIsUndoable)
{
  QComboBox* combo = panel_->decomposerCombo();
  const std::string first = doc_.settings()->decomposerId;
  for (const Plugin* p : builtinRegistry().ofKind(PluginKind::Decomposer)) {
    const int index = combo->findData(QString::fromStdString(p->id()));
    ASSERT_GE(index, 0) << p->id();
    EXPECT_EQ(combo->itemText(index), QString::fromStdString(p->label()));
    combo->setCurrentIndex(index);
    emit combo->activated(index);
    EXPECT_EQ(doc_.settings()->decomposerId, p->id());
    ParamPanel* own = section(p->id());
    if (p->schema().empty()) {
      EXPECT_EQ(own, nullptr);
      continue;
    }
    ASSERT_NE(own, nullptr) << p->id();
    for (const ParamDef& d : p->schema().defs())
      EXPECT_NE(own->field(d.key), nullptr) << p->id() << " " << d.key;
    if (p->id() != first) {
      EXPECT_EQ(window_->actions().undo->text(), "&Undo Choose decomposer");
      EXPECT_EQ(section(first), nullptr);  // only the chosen decomposer's panel is shown
    }
  }
  while (doc_.canUndo()) window_->actions().undo->trigger();
  EXPECT_EQ(doc_.settings()->decomposerId, first);
  EXPECT_EQ(combo->currentData().toString().toStdString(), first);
  EXPECT_NE(section(first), nullptr);
}

TEST_F(PlanSettingsPanel, OpeningAProjectShowsItsSettings)
{
  TempDir dir;
  {
    Document other;
    Part part;
    part.name = "empty";
    part.mesh = std::make_shared<const TriangleMesh>();
    other.setPart(part);
    other.setParam("spiral", "layer_mode", std::string("floor"));
    other.setParam(PlanSettings::kDefaultDecomposer, "points_per_rev", std::int64_t{720});
    other.saveAs(dir / "job.spira");
  }
  ASSERT_TRUE(window_->openProjectFile(qpath(dir / "job.spira")));
  EXPECT_EQ(qobject_cast<QComboBox*>(section("spiral")->field("layer_mode")->editor())->currentText(),
            "floor");
  EXPECT_EQ(
      qobject_cast<QSpinBox*>(section(PlanSettings::kDefaultDecomposer)->field("points_per_rev")->editor())
          ->value(),
      720);
}

}  // namespace
}  // namespace spira::test
