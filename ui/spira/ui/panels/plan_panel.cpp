#include "spira/ui/panels/plan_panel.h"

#include "spira/document/plan_report.h"

#include <QAction>
#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QLocale>
#include <QScrollArea>
#include <QStackedWidget>
#include <QTabWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <nlohmann/json.hpp>

#include "spira/pipeline/thermal_schema.h"
#include "spira/planning/plan_schemas.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/ui/panels/param_panel.h"
#include "spira/ui/panels/stage_progress.h"

namespace spira::ui {

namespace {

QWidget* scrolled(QWidget* content, QWidget* parent)
{
  auto* area = new QScrollArea(parent);
  area->setWidget(content);
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  return area;
}

QComboBox* pluginCombo(const PluginRegistry& registry, PluginKind kind, QWidget* parent)
{
  auto* combo = new QComboBox(parent);
  for (const Plugin* p : registry.ofKind(kind)) {
    combo->addItem(QString::fromStdString(p->label()), QString::fromStdString(p->id()));
    combo->setItemData(combo->count() - 1, QString::fromStdString(p->description()), Qt::ToolTipRole);
  }
  return combo;
}

QString mmText(double v)
{
  return QLocale().toString(v, 'f', 2) + QStringLiteral(" mm");
}

}  // namespace

PlanPanel::PlanPanel(Document& doc, const PluginRegistry& registry, QWidget* parent)
    : QDockWidget(tr("Plan"), parent), doc_(doc), registry_(registry)
{
  setObjectName(QStringLiteral("planDock"));
  auto* body = new QWidget(this);
  // Wide enough for a label, a spin box with its unit and the reset button side by side.
  body->setMinimumWidth(360);
  auto* layout = new QVBoxLayout(body);
  layout->setContentsMargins(4, 4, 4, 4);

  tabs_ = new QTabWidget(body);
  tabs_->setObjectName(QStringLiteral("planTabs"));
  auto* spiral = new ParamPanel(PlanSettings::kSpiralSection, spiralSchema());
  auto* process = new ParamPanel(PlanSettings::kProcessSection, processSchema());
  panels_[spiral->section()] = spiral;
  panels_[process->section()] = process;
  connectPanel(spiral);
  connectPanel(process);
  tabs_->addTab(scrolled(spiral, tabs_), tr("Spiral"));
  tabs_->addTab(scrolled(process, tabs_), tr("Process"));
  auto* thermal = new ParamPanel(PlanSettings::kThermalSection, thermalSchema());
  panels_[thermal->section()] = thermal;
  connectPanel(thermal);

  auto* strategy = new QWidget;
  auto* strategyLayout = new QVBoxLayout(strategy);
  strategyLayout->setContentsMargins(0, 0, 0, 0);
  auto* form = new QFormLayout;
  decomposer_ = pluginCombo(registry_, PluginKind::Decomposer, strategy);
  decomposer_->setObjectName(QStringLiteral("decomposerCombo"));
  decomposer_->setToolTip(tr("How the part is cut into generatrices, the curves the spiral climbs along"));
  closure_ = pluginCombo(registry_, PluginKind::ClosureFinder, strategy);
  closure_->setObjectName(QStringLiteral("closureCombo"));
  closure_->setToolTip(tr("Closed parts: how the point where the spiral ends is found"));
  form->addRow(tr("Decomposer"), decomposer_);
  strategyLayout->addLayout(form);
  decomposerText_ = new QLabel(strategy);
  decomposerText_->setWordWrap(true);
  decomposerText_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  strategyLayout->addWidget(decomposerText_);
  decomposerBox_ = new QVBoxLayout;
  strategyLayout->addLayout(decomposerBox_);
  auto* closureForm = new QFormLayout;
  closureForm->addRow(tr("Closure finder"), closure_);
  strategyLayout->addLayout(closureForm);
  closureText_ = new QLabel(strategy);
  closureText_->setWordWrap(true);
  closureText_->setStyleSheet(QStringLiteral("color: palette(mid);"));
  strategyLayout->addWidget(closureText_);
  closureBox_ = new QVBoxLayout;
  strategyLayout->addLayout(closureBox_);
  strategyLayout->addStretch(1);
  tabs_->addTab(scrolled(strategy, tabs_), tr("Strategy"));
  tabs_->addTab(scrolled(thermal, tabs_), tr("Thermal"));
  layout->addWidget(tabs_, 1);

  connect(decomposer_, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
    const std::string id = decomposer_->itemData(i).toString().toStdString();
    if (id != doc_.settings()->decomposerId) doc_.setDecomposer(id, tr("Choose decomposer").toStdString());
  });
  connect(closure_, QOverload<int>::of(&QComboBox::activated), this, [this](int i) {
    const std::string id = closure_->itemData(i).toString().toStdString();
    if (id != doc_.settings()->closureFinderId)
      doc_.setClosureFinder(id, tr("Choose closure finder").toStdString());
  });

  planButton_ = new QToolButton(body);
  planButton_->setObjectName(QStringLiteral("planButton"));
  planButton_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  planButton_->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
  planButton_->setMinimumHeight(34);
  QFont f = planButton_->font();
  f.setBold(true);
  planButton_->setFont(f);
  layout->addWidget(planButton_);

  // The stage bars take the verdict's place while a plan runs. One stack holds both, so its size
  // does not change when they swap: showing the bars below the verdict pushed the window taller
  // (a resize, relayout and repaint of everything: 80 ms on software OpenGL).
  status_ = new QStackedWidget(body);
  status_->setObjectName(QStringLiteral("planStatus"));
  verdict_ = new QLabel(status_);
  verdict_->setObjectName(QStringLiteral("planVerdict"));
  verdict_->setWordWrap(true);
  verdict_->setTextFormat(Qt::RichText);
  verdict_->setMargin(6);
  verdict_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  progress_ = new StageProgress(status_);
  status_->addWidget(verdict_);
  status_->addWidget(progress_);
  connect(progress_, &StageProgress::runningChanged, this, [this](bool running) {
    status_->setCurrentWidget(running ? static_cast<QWidget*>(progress_) : verdict_);
  });
  layout->addWidget(status_);
  setWidget(body);

  subscription_ = doc_.subscribe([this](const ChangeSet& c) { onDocumentChanged(c); });
  rebuildStrategyPanels();
  refreshValues();
  refreshVerdict();
}

PlanPanel::~PlanPanel()
{
  doc_.unsubscribe(subscription_);
}

void PlanPanel::setPlanAction(QAction* plan)
{
  // Not setDefaultAction: a tool button re-reads the whole action on every change and asks the
  // window to lay itself out again, which on the busy cell layout costs 50 ms each time Plan is
  // enabled or disabled. Only the enabled state changes while the window lives.
  planButton_->setText(plan->iconText());
  planButton_->setIcon(plan->icon());
  planButton_->setToolTip(plan->toolTip());
  planButton_->setEnabled(plan->isEnabled());
  connect(planButton_, &QToolButton::clicked, plan, &QAction::trigger);
  connect(plan, &QAction::changed, planButton_, [this, plan] { planButton_->setEnabled(plan->isEnabled()); });
}

ParamPanel* PlanPanel::panel(const std::string& section) const
{
  auto it = panels_.find(section);
  return it == panels_.end() ? nullptr : it->second;
}

QString PlanPanel::labelOf(const std::string& section, const std::string& key) const
{
  const ParamPanel* p = panel(section);
  const ParamDef* d = p ? p->schema().find(key) : nullptr;
  return d ? QString::fromStdString(d->label) : QString::fromStdString(key);
}

void PlanPanel::connectPanel(ParamPanel* p)
{
  connect(p, &ParamPanel::valueEdited, this,
          [this](const std::string& section, const std::string& key, const ParamValue& value) {
            doc_.setParam(section, key, value, tr("Change %1").arg(labelOf(section, key)).toStdString());
          });
  connect(p, &ParamPanel::keyResetRequested, this,
          [this](const std::string& section, const std::string& key) {
            ParamSet values = doc_.settings()->section(section);
            values.erase(key);
            doc_.setPluginParams(section, values, tr("Reset %1").arg(labelOf(section, key)).toStdString());
          });
  connect(p, &ParamPanel::sectionResetRequested, this, [this](const std::string& section) {
    doc_.setPluginParams(section, ParamSet(),
                         tr("Reset %1 parameters").arg(QString::fromStdString(section)).toStdString());
  });
}

void PlanPanel::onDocumentChanged(const ChangeSet& changes)
{
  if (changes.has(Change::Settings)) {
    if (changes.strategyChanged) rebuildStrategyPanels();
    refreshValues();
  }
  if (changes.has(Change::Results) || changes.has(Change::Part)) refreshVerdict();
}

void PlanPanel::rebuildStrategyPanels()
{
  const PlanSettings& s = *doc_.settings();
  auto rebuild = [this](const std::string& shownId, const std::string& id, QVBoxLayout* box, QLabel* text,
                        QComboBox* combo) {
    combo->setCurrentIndex(combo->findData(QString::fromStdString(id)));
    if (shownId == id && panel(id)) return;
    if (ParamPanel* old = panel(shownId)) {
      panels_.erase(shownId);
      old->deleteLater();
    }
    const Plugin* plugin = registry_.find(id);
    text->setText(plugin ? QString::fromStdString(plugin->description())
                         : tr("%1 is not available in this build.").arg(QString::fromStdString(id)));
    if (!plugin || plugin->schema().empty()) return;
    auto* p = new ParamPanel(id, plugin->schema());
    panels_[id] = p;
    connectPanel(p);
    box->addWidget(p);
  };
  rebuild(shownDecomposer_, s.decomposerId, decomposerBox_, decomposerText_, decomposer_);
  shownDecomposer_ = s.decomposerId;
  rebuild(shownClosure_, s.closureFinderId, closureBox_, closureText_, closure_);
  shownClosure_ = s.closureFinderId;
}

void PlanPanel::refreshValues()
{
  const PlanSettings& s = *doc_.settings();
  for (auto& [section, p] : panels_) p->setStored(s.section(section));
}

void PlanPanel::refreshVerdict()
{
  const Results& r = doc_.results();
  const std::optional<PlanReportSummary> plan = r.spiral ? planSummaryOf(r) : std::nullopt;
  QString text, style;
  if (!plan) {
    text = doc_.part() ? tr("No plan yet: press <b>Plan</b> (F5).")
                       : tr("Import a part, then press <b>Plan</b> (F5).");
    style = QStringLiteral("color: palette(mid);");
  } else {
    const PlanReportSummary& p = *plan;
    const bool feasible = p.feasible.value_or(false);
    const QLocale loc;
    QStringList lines;
    // The revolutions laid: those folded into the closure point are not drawn.
    const auto laid = static_cast<int>(p.revolutions - p.collapsedRevolutions);
    lines << (p.closed ? tr("%1 revolutions and the closure point, %2 points, path %3 m")
                       : tr("%1 revolutions, %2 points, path %3 m"))
                 .arg(laid)
                 .arg(loc.toString(static_cast<qlonglong>(p.points)))
                 .arg(loc.toString(p.pathLength / 1000.0, 'f', 2));
    if (p.layers)
      lines << tr("%1 layers %2 to %3 apart (%4), sharpest kink %5 deg, %6 arc start(s)")
                   .arg(p.layers->count)
                   .arg(mmText(p.layers->deltaMin), mmText(p.layers->deltaMax),
                        p.layers->spiral ? tr("one spiral through them") : tr("one arc each"))
                   .arg(loc.toString(p.layers->maxKinkDeg, 'f', 0))
                   .arg(p.layers->arcStarts);
    const PlanWindow window = p.window.value_or(PlanWindow());
    lines << tr("Deposit height %1 to %2 (window %3 to %4)")
                 .arg(mmText(p.heightMin), mmText(p.heightMax), mmText(window.hMin), mmText(window.hMax));
    // The ramps climb from the substrate and level the top across the whole window: said here so
    // the colours at the bottom and top rows do not contradict the line above.
    if (p.rampHeightMax > 0.0)
      lines
          << tr("Start-up and closing ramps %1 to %2").arg(mmText(p.rampHeightMin), mmText(p.rampHeightMax));
    // A thin-walled solid is planned on its mid-surface: say so, or the spiral inside the drawn
    // solid reads as a path off the part.
    if (p.solidWall)
      lines << tr("Thin-walled solid, wall %1 (%2 to %3): planned on its mid-surface")
                   .arg(mmText(p.solidWall->median), mmText(p.solidWall->thinnest),
                        mmText(p.solidWall->thickest));
    if (p.depositChecked)
      lines << tr("Deposit check: laid %1 to %2 on what is below, %3 % of the surface covered")
                   .arg(mmText(p.depositHeightMin), mmText(p.depositHeightMax),
                        loc.toString(100.0 * (1.0 - p.uncoveredFraction), 'f', 1));
    if (r.process && p.buildTime)
      lines << tr("Build time %1 min").arg(loc.toString(*p.buildTime / 60.0, 'f', 1));
    else
      lines << tr("Process channels out of date: press Plan again.");
    // The thermal stage's verdict in one line; its dock has the rest.
    if (const auto& heat = r.reports.thermal) {
      QString limit;
      if (heat->interpassLimit > 0.0)
        limit = heat->pointsOverLimit > 0
                    ? tr(", above the %1 °C limit at %2 points")
                          .arg(loc.toString(heat->interpassLimit, 'f', 0),
                               loc.toString(static_cast<qlonglong>(heat->pointsOverLimit)))
                    : tr(", within the %1 °C limit").arg(loc.toString(heat->interpassLimit, 'f', 0));
      lines << tr("Thermal: interpass up to %1 °C%2; %3 points at risk of collapse")
                   .arg(loc.toString(heat->maxInterpass, 'f', 0), limit,
                        loc.toString(static_cast<qlonglong>(heat->riskPoints)));
      if (heat->remediesApplied && !heat->remediesApplied->empty()) {
        QStringList cost;
        if (heat->revolutionsAdded && *heat->revolutionsAdded > 0)
          cost << tr("%n revolution(s) added", nullptr, static_cast<int>(*heat->revolutionsAdded));
        if (heat->dwells && *heat->dwells > 0)
          cost << tr("%n dwell(s) of %1 s in all (one more arc start each)", nullptr,
                     static_cast<int>(*heat->dwells))
                      .arg(loc.toString(heat->dwellTime.value_or(0.0), 'f', 0));
        cost << tr("build time +%1 min").arg(loc.toString(heat->buildTimeAdded.value_or(0.0) / 60.0, 'f', 1));
        QStringList applied;
        for (const std::string& remedy : *heat->remediesApplied) applied << QString::fromStdString(remedy);
        lines << tr("Re-planned (%1): %2")
                     .arg(applied.join(QStringLiteral(", ")), cost.join(QStringLiteral(", ")));
      }
      if (heat->whyNotMet)
        lines << tr("Interpass limit not met: %1")
                     .arg(QString::fromStdString(*heat->whyNotMet).toHtmlEscaped());
    }
    if (feasible) {
      text = tr("<b>Feasible plan</b><br>%1").arg(lines.join(QStringLiteral("<br>")));
      style = QStringLiteral(
          "background: #e3f4e1; color: #1d5a1a; border: 1px solid #9fcf99; border-radius: 3px;");
    } else {
      const auto flagged = static_cast<int>(p.flagged);
      const QString why =
          flagged > 0 ? tr("the deposit check rejects %n point(s) (listed in Messages)", nullptr, flagged)
                      : tr("%1 % of the surface is left uncovered")
                            .arg(loc.toString(100.0 * p.uncoveredFraction, 'f', 1));
      text = tr("<b>Infeasible plan:</b> %1<br>%2").arg(why, lines.join(QStringLiteral("<br>")));
      style = QStringLiteral(
          "background: #fbe3e1; color: #8a1c14; border: 1px solid #e3a29b; border-radius: 3px;");
    }
  }
  verdict_->setText(text);
  verdict_->setStyleSheet(style);
  verdict_->setProperty("feasible", plan ? QVariant(plan->feasible.value_or(false)) : QVariant());
}

}  // namespace spira::ui
