#include "spira/ui/views/offending_points.h"

#include <algorithm>
#include <functional>
#include <map>
#include <vector>

#include <QListWidget>
#include <QLocale>
#include <nlohmann/json.hpp>

#include "spira/document/results.h"
#include "spira/pipeline/document_plan.h"
#include "spira/ui/panels/log_panel.h"

namespace spira::ui {

namespace {

// One message per point, "Point i (revolution r): " and what is wrong there.
struct Lister {
  LogPanel& log;
  QListWidget& list;
  const Trajectory& path;
  int role;
  int maxPerKind;

  void operator()(const std::vector<size_t>& points, const std::function<QString(size_t)>& what,
                  const QString& rest) const
  {
    const QLocale loc;
    const size_t listed = std::min(points.size(), static_cast<size_t>(maxPerKind));
    for (size_t k = 0; k < listed; ++k) {
      const size_t i = points[k];
      const QString message = QObject::tr("Point %1 (revolution %2): %3")
                                  .arg(loc.toString(static_cast<qulonglong>(i)))
                                  .arg(path.points[i].revolution + 1)
                                  .arg(what(i));
      log.warning(message, QObject::tr("Click this message to select the point."));
      list.item(list.count() - 1)->setData(role, static_cast<long long>(points[k]));
    }
    if (points.size() > listed)
      log.info(rest.arg(QLocale().toString(static_cast<qulonglong>(points.size() - listed))));
  }
};

// The deposit check's points, from the spiral stage's report (report.json's deposit_check).
void listDepositFlags(const Lister& lister, const Results& results)
{
  const std::optional<PlanReportSummary> plan = planSummaryOf(results);
  if (!plan || !plan->depositChecked) return;
  std::vector<size_t> flagged;
  std::map<size_t, QString> what;
  const QLocale loc;
  for (const DepositFlagSummary& f : plan->flaggedPoints) {
    const size_t i = f.point;
    if (i >= lister.path.size()) continue;
    const std::string& kind = f.kind;
    const QString mm = f.height ? loc.toString(*f.height, 'f', 2) : QString();
    QString text;
    if (kind == "below_deposit")
      text = QObject::tr("it lies %1 mm under material already laid.")
                 .arg(loc.toString(-f.height.value_or(0.0), 'f', 2));
    else if (kind == "thin")
      text = QObject::tr("the bead under it is only %1 mm below: thinner than the process lays.").arg(mm);
    else if (kind == "thick")
      text = QObject::tr("the material below is %1 mm away: thicker than the process lays.").arg(mm);
    else if (kind == "jump")
      text = QObject::tr("reached by a %1 mm jump with the arc on.").arg(mm);
    else
      text =
          mm.isEmpty()
              ? QObject::tr("nothing below it: the bead would be laid in mid-air.")
              : QObject::tr("the material below is %1 mm away: the bead would be laid in mid-air.").arg(mm);
    if (what.count(i) == 0) flagged.push_back(i);
    what[i] += (what[i].isEmpty() ? QString() : QStringLiteral(" ")) + text;
  }
  lister(
      flagged, [&](size_t i) { return what[i]; },
      QObject::tr(
          "... and %1 more point(s) the deposit check rejected (report.json's deposit_check lists them)."));
}

}  // namespace

void listOffendingPoints(LogPanel& log, QListWidget& list, const Results& results, int pointRole,
                         int maxPerKind)
{
  if (!results.process) return;
  const Trajectory& path = *results.process;
  const Lister lister{log, list, path, pointRole, maxPerKind};
  const QLocale loc;
  if (const std::optional<PlanWindow> window = planWindow(results)) {
    std::vector<size_t> outside;
    for (size_t i = 0; i < path.size(); ++i)
      if (window->outside(path.points[i].height)) outside.push_back(i);
    lister(
        outside,
        [&](size_t i) {
          return QObject::tr("deposit height %1 mm is outside the window %2 .. %3 mm.")
              .arg(loc.toString(path.points[i].height, 'f', 3), loc.toString(window->hMin, 'f', 2),
                   loc.toString(window->hMax, 'f', 2));
        },
        QObject::tr("... and %1 more point(s) outside the window (see the process chart's magenta dots)."));
  }

  listDepositFlags(lister, results);

  const auto& k = results.kinematics;
  if (!k || k->checks.size() != path.size()) return;
  std::vector<size_t> unreachable, beyondLimit, colliding;
  for (size_t i = 0; i < k->checks.size(); ++i) {
    const KinematicsCheck& c = k->checks[i];
    if (!c.reachable)
      unreachable.push_back(i);
    else if (c.limitMarginDeg < 0.0)
      beyondLimit.push_back(i);
    if (c.collision) colliding.push_back(i);
  }
  lister(
      unreachable, [](size_t) { return QObject::tr("the robot cannot reach it."); },
      QObject::tr("... and %1 more point(s) out of reach (red on the spiral)."));
  lister(
      beyondLimit,
      [&](size_t i) {
        return QObject::tr("an axis is %1 deg beyond its limit.")
            .arg(loc.toString(-k->checks[i].limitMarginDeg, 'f', 1));
      },
      QObject::tr("... and %1 more point(s) beyond an axis limit (see the joint chart)."));
  lister(
      colliding, [](size_t) { return QObject::tr("the torch or a robot link collides there."); },
      QObject::tr("... and %1 more colliding point(s) (red on the spiral)."));
}

}  // namespace spira::ui
