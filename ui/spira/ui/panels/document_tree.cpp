#include "spira/ui/panels/document_tree.h"

#include <QFileInfo>
#include <QHeaderView>
#include <QLocale>
#include <QSet>

#include "spira/base/units.h"
#include "spira/document/document.h"
#include "spira/mesh/mesh_report.h"
#include "spira/pipeline/thermal_schema.h"

namespace spira::ui {

namespace {

QString count(size_t n)
{
  return QLocale().toString(static_cast<qulonglong>(n));
}

// Lengths to 0.01 mm without trailing zeros: "60", "12.5", "0.25".
QString number(double v)
{
  QString text = QLocale().toString(v, 'f', 2);
  const QChar point = QLocale().decimalPoint();
  if (text.contains(point)) {
    while (text.endsWith('0')) text.chop(1);
    if (text.endsWith(point)) text.chop(1);
  }
  return text;
}

QString mm(double v)
{
  return number(v) + QStringLiteral(" mm");
}

QTreeWidgetItem* addTop(QTreeWidget* tree, const QString& title, const QString& value)
{
  auto* item = new QTreeWidgetItem(tree, {title, value});
  QFont f = item->font(0);
  f.setBold(true);
  item->setFont(0, f);
  return item;
}

QTreeWidgetItem* addRow(QTreeWidgetItem* parent, const QString& key, const QString& value)
{
  auto* item = new QTreeWidgetItem(parent, {key, value});
  item->setToolTip(1, value);
  return item;
}

void fillPart(QTreeWidget* tree, const Document& doc, const MeshReport* report)
{
  const auto& part = doc.part();
  if (!part) {
    addTop(tree, QObject::tr("Part"), QObject::tr("none (File > Import Part...)"));
    return;
  }
  QTreeWidgetItem* top = addTop(tree, QObject::tr("Part"), QString::fromStdString(part->name));
  if (part->mesh) {
    addRow(top, QObject::tr("Triangles"), count(part->mesh->faceCount()));
    addRow(top, QObject::tr("Vertices"), count(part->mesh->vertexCount()));
  }
  if (report) {
    QTreeWidgetItem* kind =
        addRow(top, QObject::tr("Type"), QString::fromUtf8(partClassName(report->partClass)));
    kind->setToolTip(1, QString::fromStdString(report->classReason));
    addRow(top, QObject::tr("Boundary loops"), count(report->boundaryLoops.size()));
    const Vec3 size = report->bounds.size();
    addRow(top, QObject::tr("Size"),
           QStringLiteral("%1 x %2 x %3 mm").arg(number(size.x()), number(size.y()), number(size.z())));
    addRow(top, QObject::tr("Area"), QLocale().toString(report->area, 'f', 1) + QStringLiteral(" mm²"));
    size_t defects = 0;
    for (const MeshIssue& issue : report->issues) defects += issue.count;
    addRow(top, QObject::tr("Defects"), defects == 0 ? QObject::tr("none") : count(defects));
  }
  if (!part->sourcePath.empty()) {
    addRow(top, QObject::tr("Source"), QFileInfo(QString::fromStdString(part->sourcePath)).fileName())
        ->setToolTip(1, QString::fromStdString(part->sourcePath));
  }
  addRow(top, QObject::tr("Source unit"),
         QString::fromUtf8(lengthUnitSymbol(part->sourceUnit).data(),
                           static_cast<int>(lengthUnitSymbol(part->sourceUnit).size())));
}

void fillSubstrate(QTreeWidget* tree, const Document& doc)
{
  const Substrate& s = *doc.substrate();
  if (s.kind == Substrate::Kind::Plane) {
    QTreeWidgetItem* top = addTop(tree, QObject::tr("Substrate"), QObject::tr("plane"));
    addRow(top, QObject::tr("Height"), mm(s.planeZ));
    addRow(top, QObject::tr("Normal"),
           QStringLiteral("(%1, %2, %3)")
               .arg(s.planeNormal.x(), 0, 'g', 4)
               .arg(s.planeNormal.y(), 0, 'g', 4)
               .arg(s.planeNormal.z(), 0, 'g', 4));
  } else {
    QTreeWidgetItem* top = addTop(tree, QObject::tr("Substrate"), QString::fromStdString(s.meshName));
    if (s.mesh) addRow(top, QObject::tr("Triangles"), count(s.mesh->faceCount()));
  }
}

void fillScan(QTreeWidget* tree, const Document& doc)
{
  const auto& scan = doc.scan();
  if (!scan) return;
  QTreeWidgetItem* top =
      addTop(tree, QObject::tr("Scan"), QFileInfo(QString::fromStdString(scan->file)).fileName());
  addRow(
      top, QObject::tr("Placed"),
      QObject::tr("%1 mm, %2°")
          .arg(QLocale().toString(scan->T_part_scan.translation().norm(), 'f', 3),
               QLocale().toString(radToDeg(Eigen::AngleAxisd(scan->T_part_scan.linear()).angle()), 'f', 3)));
  addRow(top, QObject::tr("Residual"), mm(scan->rmsMm));
  if (scan->depositedTo > 0) addRow(top, QObject::tr("Taken at point"), count(scan->depositedTo));
}

void fillCell(QTreeWidget* tree, const Document& doc)
{
  const auto& cell = doc.cell();
  if (!cell) {
    addTop(tree, QObject::tr("Cell"), QObject::tr("none"));
    return;
  }
  QTreeWidgetItem* top = addTop(tree, QObject::tr("Cell"), QString::fromStdString(cell->name));
  addRow(top, QObject::tr("Robot"), QFileInfo(QString::fromStdString(cell->robotUrdf)).fileName());
  addRow(top, QObject::tr("Controller"), QString::fromUtf8(controllerFamilyName(cell->controller)));
  addRow(top, QObject::tr("Positioner"),
         cell->hasPositioner() ? QFileInfo(QString::fromStdString(cell->positionerUrdf)).fileName()
                               : QObject::tr("none"));
}

void fillSettings(QTreeWidget* tree, const Document& doc)
{
  const PlanSettings& s = *doc.settings();
  QTreeWidgetItem* top = addTop(tree, QObject::tr("Plan settings"), QString());
  addRow(top, QObject::tr("Decomposer"), QString::fromStdString(s.decomposerId));
  addRow(top, QObject::tr("Closure finder"), QString::fromStdString(s.closureFinderId));
  for (const auto& [section, values] : s.params) {
    if (values.values().empty()) continue;  // reset to defaults
    addRow(top, QString::fromStdString(section),
           QObject::tr("%n value(s) set", nullptr, static_cast<int>(values.values().size())));
  }
}

QString trajectoryText(const std::shared_ptr<const Trajectory>& t)
{
  return QObject::tr("%1 points, %2").arg(count(t->size()), mm(t->length()));
}

void fillResults(QTreeWidget* tree, const Document& doc)
{
  const Results& r = doc.results();
  int present = 0;
  for (int i = 0; i < kStageCount; ++i) present += r.has(stageAt(i)) ? 1 : 0;
  // The thermal stage counts when it is switched on (or was when its results were made).
  const bool thermal =
      r.thermal || thermalStageEnabled(doc.settings()->section(PlanSettings::kThermalSection));
  const int stages = kStageCount - (thermal ? 0 : 1);
  QTreeWidgetItem* top =
      addTop(tree, QObject::tr("Results"),
             present == 0 ? QObject::tr("none") : QObject::tr("%1 of %2 stages").arg(present).arg(stages));
  const QString missing = QObject::tr("not computed");
  addRow(top, QObject::tr("Field"),
         r.field ? QObject::tr("%1 values").arg(count(r.field->values.size())) : missing);
  addRow(top, QObject::tr("Generatrices"),
         r.generatrices ? QObject::tr("%1 curves").arg(count(r.generatrices->lines.size())) : missing);
  addRow(top, QObject::tr("Spiral"), r.spiral ? trajectoryText(r.spiral) : missing);
  addRow(top, QObject::tr("Process"), r.process ? trajectoryText(r.process) : missing);
  if (thermal)
    addRow(top, QObject::tr("Thermal"),
           r.thermal ? QObject::tr("%1 nodes, %2 frames")
                           .arg(count(r.thermal->nodes.size()))
                           .arg(count(r.thermal->frames.size()))
                     : missing);
  addRow(top, QObject::tr("Kinematics"), r.kinematics ? QObject::tr("computed") : missing);
  addRow(top, QObject::tr("Export"),
         r.exported ? QObject::tr("%n file(s) written", "", static_cast<int>(r.exported->files.size()))
                    : missing);
}

}  // namespace

DocumentTree::DocumentTree(QWidget* parent) : QTreeWidget(parent)
{
  setObjectName("documentTree");
  setColumnCount(2);
  setHeaderLabels({tr("Object"), tr("Value")});
  header()->setSectionResizeMode(0, QHeaderView::ResizeToContents);
  header()->setStretchLastSection(true);
  setAlternatingRowColors(true);
  setUniformRowHeights(true);
  setRootIsDecorated(true);
}

QTreeWidgetItem* DocumentTree::section(const QString& title) const
{
  for (int i = 0; i < topLevelItemCount(); ++i) {
    if (topLevelItem(i)->text(0) == title) return topLevelItem(i);
  }
  return nullptr;
}

void DocumentTree::refresh(const Document& doc, const MeshReport* partReport)
{
  // Sections start expanded; after that the user's choice is kept.
  QSet<QString> collapsed;
  for (int i = 0; i < topLevelItemCount(); ++i) {
    if (!topLevelItem(i)->isExpanded()) collapsed.insert(topLevelItem(i)->text(0));
  }
  const bool first = topLevelItemCount() == 0;
  setUpdatesEnabled(false);
  clear();
  fillPart(this, doc, partReport);
  fillSubstrate(this, doc);
  fillScan(this, doc);
  fillCell(this, doc);
  fillSettings(this, doc);
  fillResults(this, doc);
  for (int i = 0; i < topLevelItemCount(); ++i) {
    QTreeWidgetItem* item = topLevelItem(i);
    item->setExpanded(first || !collapsed.contains(item->text(0)));
  }
  setUpdatesEnabled(true);
}

}  // namespace spira::ui
