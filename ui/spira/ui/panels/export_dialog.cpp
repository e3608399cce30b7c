#include "spira/ui/panels/export_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QFileDialog>
#include <QFileInfo>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QScrollArea>
#include <QSplitter>
#include <QStackedWidget>
#include <QTabWidget>
#include <QTimer>
#include <QToolButton>
#include <QVBoxLayout>

#include "spira/document/document.h"
#include "spira/pipeline/prep_schema.h"
#include "spira/plugin/plugin_registry.h"
#include "spira/ui/jobs/task_runner.h"
#include "spira/ui/panels/log_panel.h"
#include "spira/ui/panels/param_panel.h"

namespace spira::ui {

namespace {

const char* const kPrepSection = kPrepSectionName;

QString fromStd(const std::string& s)
{
  return QString::fromStdString(s);
}

QScrollArea* scrolled(QWidget* content, QWidget* parent)
{
  auto* area = new QScrollArea(parent);
  area->setWidget(content);
  area->setWidgetResizable(true);
  area->setFrameShape(QFrame::NoFrame);
  return area;
}

}  // namespace

ExportDialog::ExportDialog(Document& doc, const PluginRegistry& registry, LogPanel* log, QWidget* parent)
    : QDialog(parent), doc_(doc), registry_(registry), log_(log)
{
  setObjectName(QStringLiteral("exportDialog"));
  setWindowTitle(tr("Export Robot Program"));
  resize(1120, 720);
  tasks_ = new TaskRunner(this, this);
  debounce_ = new QTimer(this);
  debounce_->setSingleShot(true);
  debounce_->setInterval(250);
  connect(debounce_, &QTimer::timeout, this, &ExportDialog::startPreview);

  QToolButton* browse = nullptr;
  QWidget* settings = buildSettingsSide(browse);
  QWidget* preview = buildPreviewSide();
  layOut(settings, preview);
  connectControls(browse);
  // The preview follows the plan and the cell while the dialog is open.
  subscription_ = doc_.subscribe([this](const ChangeSet& c) {
    if (isVisible() && !exporting_ &&
        (c.has(Change::Results) || c.has(Change::Cell) || c.has(Change::Part) || c.has(Change::Settings)))
      refresh();
  });
}

QWidget* ExportDialog::buildSettingsSide(QToolButton*& browse)
{
  // Left: what to write and where.
  auto* settings = new QWidget(this);
  auto* left = new QVBoxLayout(settings);
  left->setContentsMargins(0, 0, 6, 0);
  auto* form = new QFormLayout;
  format_ = new QComboBox(settings);
  format_->setObjectName(QStringLiteral("exportFormat"));
  formatText_ = new QLabel(settings);
  formatText_->setWordWrap(true);
  formatText_->setStyleSheet(QStringLiteral("color: palette(dark);"));
  auto* folderRow = new QHBoxLayout;
  folder_ = new QLineEdit(settings);
  folder_->setObjectName(QStringLiteral("exportFolder"));
  folder_->setPlaceholderText(tr("Folder the program files go to"));
  folder_->setText(QDir::homePath());
  browse = new QToolButton(settings);
  browse->setText(tr("Browse..."));
  folderRow->addWidget(folder_, 1);
  folderRow->addWidget(browse);
  form->addRow(tr("Format"), format_);
  form->addRow(QString(), formatText_);
  form->addRow(tr("Output folder"), folderRow);
  left->addLayout(form);
  left->addWidget(buildSettingTabs(settings), 1);
  for (auto& [id, panel] : exporterPanels_) connectSettingsPanel(panel);
  connectSettingsPanel(prepPanel_);
  prepPanel_->setStored(values_[kPrepSection]);
  return settings;
}

QTabWidget* ExportDialog::buildSettingTabs(QWidget* settings)
{
  auto* settingTabs = new QTabWidget(settings);
  exporterPages_ = new QStackedWidget(settingTabs);
  for (const Plugin* p : registry_.ofKind(PluginKind::Exporter)) {
    const auto* e = static_cast<const ExporterPlugin*>(p);
    format_->addItem(fromStd(e->label()), fromStd(e->id()));
    format_->setItemData(format_->count() - 1, fromStd(e->description()), Qt::ToolTipRole);
    auto* panel = new ParamPanel(e->id(), e->schema(), exporterPages_);
    exporterPanels_[e->id()] = panel;
    exporterPages_->addWidget(scrolled(panel, exporterPages_));
    values_[e->id()] = doc_.settings()->section(e->id());
    panel->setStored(values_[e->id()]);
  }
  prepPanel_ = new ParamPanel(kPrepSection, prepSchema(), settingTabs);
  settingTabs->addTab(exporterPages_, tr("Program"));
  settingTabs->addTab(scrolled(prepPanel_, settingTabs), tr("Path preparation"));
  return settingTabs;
}

void ExportDialog::connectSettingsPanel(ParamPanel* panel)
{
  // A panel names its own section (an exporter's id or "prep") in what it emits.
  connect(panel, &ParamPanel::valueEdited, this,
          [this, panel](const std::string& section, const std::string& key, const ParamValue& v) {
            values_[section].set(key, v);
            panel->setStored(values_[section]);
            schedulePreview();
          });
  connect(panel, &ParamPanel::keyResetRequested, this,
          [this, panel](const std::string& section, const std::string& key) {
            values_[section].erase(key);
            panel->setStored(values_[section]);
            schedulePreview();
          });
  connect(panel, &ParamPanel::sectionResetRequested, this, [this, panel](const std::string& section) {
    values_[section] = ParamSet();
    panel->setStored(values_[section]);
    schedulePreview();
  });
}

QWidget* ExportDialog::buildPreviewSide()
{
  // Right: what would be written, and what to know first.
  auto* preview = new QWidget(this);
  auto* right = new QVBoxLayout(preview);
  right->setContentsMargins(6, 0, 0, 0);
  warnings_ = new QLabel(preview);
  warnings_->setObjectName(QStringLiteral("exportWarnings"));
  warnings_->setWordWrap(true);
  warnings_->setTextFormat(Qt::RichText);
  warnings_->setContentsMargins(10, 6, 10, 6);
  summary_ = new QLabel(preview);
  summary_->setObjectName(QStringLiteral("exportSummary"));
  summary_->setWordWrap(true);
  previewTabs_ = new QTabWidget(preview);
  previewTabs_->setObjectName(QStringLiteral("exportPreview"));
  right->addWidget(warnings_);
  right->addWidget(summary_);
  right->addWidget(previewTabs_, 1);
  return preview;
}

void ExportDialog::layOut(QWidget* settings, QWidget* preview)
{
  auto* split = new QSplitter(Qt::Horizontal, this);
  split->addWidget(settings);
  split->addWidget(preview);
  split->setStretchFactor(0, 0);
  split->setStretchFactor(1, 1);
  split->setSizes({440, 680});
  split->setChildrenCollapsible(false);

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
  exportButton_ = buttons->addButton(tr("&Export"), QDialogButtonBox::AcceptRole);
  exportButton_->setObjectName(QStringLiteral("exportButton"));
  exportButton_->setDefault(true);
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  connect(exportButton_, &QPushButton::clicked, this, &ExportDialog::exportProgram);

  auto* layout = new QVBoxLayout(this);
  layout->addWidget(split, 1);
  layout->addWidget(buttons);
}

void ExportDialog::connectControls(QToolButton* browse)
{
  connect(format_, qOverload<int>(&QComboBox::currentIndexChanged), this, [this](int i) {
    exporterPages_->setCurrentIndex(i);
    const auto* e = &registry_.exporter(format_->itemData(i).toString().toStdString());
    formatText_->setText(fromStd(e->fileDescription()));
    schedulePreview();
  });
  connect(browse, &QToolButton::clicked, this, &ExportDialog::browse);
  connect(folder_, &QLineEdit::textChanged, this, &ExportDialog::refreshExportButton);
  if (format_->count() > 0) {
    exporterPages_->setCurrentIndex(0);
    formatText_->setText(fromStd(registry_.exporter(exporterId()).fileDescription()));
  }
}

ExportDialog::~ExportDialog()
{
  doc_.unsubscribe(subscription_);
  // The worker may still be writing into the temporary folder; the runner joins it.
  delete tasks_;
  tasks_ = nullptr;
}

void ExportDialog::refresh()
{
  for (auto& [id, panel] : exporterPanels_) {
    values_[id] = doc_.settings()->section(id);
    panel->setStored(values_[id]);
  }
  refreshExportButton();
  schedulePreview();
}

void ExportDialog::showEvent(QShowEvent* event)
{
  QDialog::showEvent(event);
  refresh();
}

void ExportDialog::setExporter(const std::string& id)
{
  const int i = format_->findData(fromStd(id));
  if (i >= 0) format_->setCurrentIndex(i);
}

std::string ExportDialog::exporterId() const
{
  return format_->currentData().toString().toStdString();
}

void ExportDialog::setOutputFolder(const QString& dir)
{
  folder_->setText(dir);
}

QString ExportDialog::outputFolder() const
{
  return folder_->text().trimmed();
}

void ExportDialog::setExporterValue(const std::string& key, const ParamValue& value)
{
  const std::string id = exporterId();
  values_[id].set(key, value);
  exporterPanels_.at(id)->setStored(values_[id]);
  schedulePreview();
}

ParamPanel* ExportDialog::exporterPanel(const std::string& id) const
{
  const auto it = exporterPanels_.find(id);
  return it == exporterPanels_.end() ? nullptr : it->second;
}

bool ExportDialog::previewBusy() const
{
  return previewPending_ || debounce_->isActive() || (tasks_->busy() && !exporting_);
}

ExportRequest ExportDialog::request() const
{
  const auto& part = doc_.part();
  // The motion was solved with the part turned on its mount as it is placed: so are the targets.
  std::shared_ptr<const CellRecord> cell = doc_.cell();
  if (cell && part) cell = std::make_shared<const CellRecord>(cellForPlacement(*cell, part->T_world_part));
  ExportRequest r = makeExportRequest(doc_.results(), part ? part->name : std::string("part"), cell);
  r.exporterId = exporterId();
  const auto values = values_.find(r.exporterId);
  if (values != values_.end()) r.exporterParams = values->second;
  const auto prep = values_.find(kPrepSection);
  if (prep != values_.end()) r.prepParams = prep->second;
  return r;
}

void ExportDialog::refreshExportButton()
{
  const bool planned = doc_.results().process != nullptr;
  exportButton_->setEnabled(planned && !outputFolder().isEmpty() && !exporting_);
  exportButton_->setToolTip(planned ? tr("Write the program files into the output folder")
                                    : tr("Plan the part first (F5): there is nothing to export yet"));
}

void ExportDialog::schedulePreview()
{
  previewPending_ = true;
  debounce_->start();
}

void ExportDialog::startPreview()
{
  if (tasks_->busy()) {
    // The running preview is out of date; the next one starts when it has stopped.
    if (!exporting_) tasks_->cancel();
    debounce_->start();
    return;
  }
  previewPending_ = false;
  if (!doc_.results().process) {
    previewTabs_->clear();
    summary_->setText(tr("Plan the part first (F5): the preview shows the program of the planned path."));
    showWarnings(nullptr);
    previewOk_ = false;
    emit previewUpdated(false);
    return;
  }
  summary_->setText(tr("Preparing the preview..."));
  auto result = std::make_shared<ExportPreview>();
  const ExportRequest req = request();
  const PluginRegistry* registry = &registry_;
  tasks_->start(
      tr("Export preview"),
      [registry, req, result](Progress& progress) {
        *result = previewExport(*registry, req, kPreviewLines, progress);
      },
      [this, result](const TaskOutcome& outcome) { finishPreview(outcome, result); },
      TaskRunner::Display::Signals);
}

void ExportDialog::finishPreview(const TaskOutcome& outcome, const std::shared_ptr<ExportPreview>& preview)
{
  if (outcome.status == TaskOutcome::Status::Cancelled) return;
  previewTabs_->clear();
  if (!outcome.succeeded()) {
    summary_->setText(tr("<b>The program cannot be written:</b> %1<br>%2")
                          .arg(outcome.message.toHtmlEscaped(), outcome.hint.toHtmlEscaped()));
    showWarnings(nullptr);
    previewOk_ = false;
    emit previewUpdated(false);
    return;
  }
  const QFont mono = QFontDatabase::systemFont(QFontDatabase::FixedFont);
  for (const PreviewFile& f : preview->files) {
    auto* text = new QPlainTextEdit(previewTabs_);
    text->setReadOnly(true);
    text->setFont(mono);
    text->setLineWrapMode(QPlainTextEdit::NoWrap);
    QStringList lines;
    for (const std::string& l : f.lines) lines << fromStd(l);
    if (f.totalLines > f.lines.size())
      lines << QString()
            << tr("... %n more line(s)", nullptr, static_cast<int>(f.totalLines - f.lines.size()));
    text->setPlainText(lines.join('\n'));
    previewTabs_->addTab(text, fromStd(f.name));
  }
  const ExportOutcome& o = preview->outcome;
  const QLocale loc;
  QStringList names;
  for (const PreviewFile& f : preview->files) names << fromStd(f.name);
  summary_->setText(
      tr("%1 planned points become %2 robot targets (chord deviation at most %3 mm) in %n file(s): %4.",
         nullptr, static_cast<int>(preview->files.size()))
          .arg(loc.toString(static_cast<qulonglong>(o.prep.pointsIn)),
               loc.toString(static_cast<qulonglong>(o.robotTargets)),
               loc.toString(o.prep.maxChordDeviation, 'f', 3), names.join(QStringLiteral(", "))));
  showWarnings(preview.get());
  previewOk_ = true;
  emit previewUpdated(true);
}

void ExportDialog::showWarnings(const ExportPreview* preview)
{
  warningList_.clear();
  for (const std::string& w : exportWarnings(doc_.results(), preview)) warningList_ << fromStd(w);
  if (doc_.results().process && !doc_.cell())
    warningList_.prepend(
        tr("No robot cell is set: the targets are torch poses in the part frame, without "
           "joint configuration or positioner axes."));
  if (warningList_.isEmpty()) {
    warnings_->setText(
        tr("&#10004; No warnings: every point is inside the process window and, with a cell, "
           "reachable."));
    warnings_->setStyleSheet(QStringLiteral(
        "background: #e6f4ea; color: #1e4620; border: 1px solid #9fd3ad; border-radius: 4px;"));
    return;
  }
  QString html = tr("<b>Check before writing:</b><ul style='margin: 2px 0 0 -24px;'>");
  for (const QString& w : warningList_) html += QStringLiteral("<li>%1</li>").arg(w.toHtmlEscaped());
  warnings_->setText(html + QStringLiteral("</ul>"));
  warnings_->setStyleSheet(
      QStringLiteral("background: #fff4d6; color: #4a3800; border: 1px solid #e3c169; border-radius: 4px;"));
}

void ExportDialog::browse()
{
  const QString dir = QFileDialog::getExistingDirectory(this, tr("Output folder"), outputFolder());
  if (!dir.isEmpty()) setOutputFolder(dir);
}

void ExportDialog::exportProgram()
{
  if (exporting_) return;
  const QString dir = outputFolder();
  auto fail = [this](const QString& message, const QString& hint) {
    summary_->setText(tr("<b>Not exported:</b> %1<br>%2").arg(message.toHtmlEscaped(), hint.toHtmlEscaped()));
    if (log_) log_->error(message, hint);
    emit exported(false, {});
  };
  if (!doc_.results().process) {
    fail(tr("There is no planned path to export."), tr("Plan the part first (F5)."));
    return;
  }
  const QFileInfo info(dir);
  if (dir.isEmpty() || !info.isDir() || !info.isWritable()) {
    fail(tr("The output folder '%1' does not exist or cannot be written.").arg(dir),
         tr("Choose an existing folder you may write to."));
    return;
  }
  if (tasks_->busy()) {
    tasks_->cancel();
    tasks_->waitForFinished();
  }
  debounce_->stop();
  previewPending_ = false;
  exporting_ = true;
  refreshExportButton();
  const ExportRequest req = request();
  auto result = std::make_shared<ExportOutcome>();
  const PluginRegistry* registry = &registry_;
  const std::filesystem::path out = dir.toStdString();
  summary_->setText(tr("Writing the program..."));
  tasks_->start(
      tr("Exporting"),
      [registry, req, out, result](Progress& progress) {
        *result = runExport(*registry, req, out, progress);
      },
      [this, result, dir, req](const TaskOutcome& outcome) {
        finishExport(outcome, result, dir, req.exporterId, req.exporterParams);
      },
      TaskRunner::Display::Signals);
}

void ExportDialog::finishExport(const TaskOutcome& outcome, const std::shared_ptr<ExportOutcome>& result,
                                const QString& dir, const std::string& exporterId, const ParamSet& params)
{
  exporting_ = false;
  refreshExportButton();
  if (!outcome.succeeded()) {
    const QString message =
        outcome.status == TaskOutcome::Status::Cancelled ? tr("The export was cancelled.") : outcome.message;
    summary_->setText(
        tr("<b>Not exported:</b> %1<br>%2").arg(message.toHtmlEscaped(), outcome.hint.toHtmlEscaped()));
    if (log_) log_->error(tr("Export failed: %1").arg(message), outcome.hint);
    emit exported(false, {});
    return;
  }
  // The values written with are the document's from now on (one undo step, only when they changed).
  if (doc_.settings()->section(exporterId).values() != params.values())
    doc_.setPluginParams(exporterId, params, "Change export settings");
  // The export stage of the document: what was written, until the plan or these settings change.
  ExportStageResult written{exporterId, {}};
  for (const auto& f : result->result.files) written.files.push_back(f.string());
  doc_.setExport(std::make_shared<const ExportStageResult>(std::move(written)));
  QStringList files;
  for (const auto& f : result->result.files) files << QDir::toNativeSeparators(fromStd(f.string()));
  QStringList names;
  for (const auto& f : result->result.files) names << fromStd(f.filename().string());
  const QString text = tr("Exported %1 robot targets to %2: %3.")
                           .arg(QLocale().toString(static_cast<qulonglong>(result->robotTargets)),
                                QDir::toNativeSeparators(dir), names.join(QStringLiteral(", ")));
  summary_->setText(text);
  if (log_) {
    log_->info(text);
    for (const std::string& w : result->result.warnings) log_->warning(fromStd(w));
  }
  emit exported(true, files);
}

}  // namespace spira::ui
