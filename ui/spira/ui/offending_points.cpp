#include "spira/ui/offending_points.h"

#include <algorithm>
#include <functional>
#include <vector>

#include <QListWidget>
#include <QLocale>

#include "spira/document/results.h"
#include "spira/ui/log_panel.h"
#include "spira/ui/plan_job.h"

namespace spira::ui {

namespace {

struct Lister {
  LogPanel& log;
  QListWidget& list;
  int role;
  int maxPerKind;

  void operator()(const std::vector<size_t>& points, const std::function<QString(size_t)>& message,
                  const QString& rest) const
  {
    const size_t listed = std::min(points.size(), static_cast<size_t>(maxPerKind));
    for (size_t k = 0; k < listed; ++k) {
      log.warning(message(points[k]), QObject::tr("Click this message to select the point."));
      list.item(list.count() - 1)->setData(role, static_cast<long long>(points[k]));
    }
    if (points.size() > listed)
      log.info(rest.arg(QLocale().toString(static_cast<qulonglong>(points.size() - listed))));
  }
};

}  // namespace

void listOffendingPoints(LogPanel& log, QListWidget& list, const Results& results, int pointRole,
                         int maxPerKind)
{
  if (!results.process) return;
  const Lister lister{log, list, pointRole, maxPerKind};
  const QLocale loc;
  const Trajectory& path = *results.process;
  if (const std::optional<PlanWindow> window = planWindow(results)) {
    std::vector<size_t> outside;
    for (size_t i = 0; i < path.size(); ++i)
      if (window->outside(path.points[i].height)) outside.push_back(i);
    lister(
        outside,
        [&](size_t i) {
          const TrajectoryPoint& p = path.points[i];
          return QObject::tr(
                     "Point %1 (revolution %2): deposit height %3 mm is outside the window %4 .. %5 mm.")
              .arg(loc.toString(static_cast<qulonglong>(i)))
              .arg(p.revolution + 1)
              .arg(loc.toString(p.height, 'f', 3), loc.toString(window->hMin, 'f', 2),
                   loc.toString(window->hMax, 'f', 2));
        },
        QObject::tr("... and %1 more point(s) outside the window (see the process chart's magenta dots)."));
  }

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
  const auto revolution = [&](size_t i) { return path.points[i].revolution + 1; };
  lister(
      unreachable,
      [&](size_t i) {
        return QObject::tr("Point %1 (revolution %2): the robot cannot reach it.")
            .arg(loc.toString(static_cast<qulonglong>(i)))
            .arg(revolution(i));
      },
      QObject::tr("... and %1 more point(s) out of reach (red on the spiral)."));
  lister(
      beyondLimit,
      [&](size_t i) {
        return QObject::tr("Point %1 (revolution %2): an axis is %3 deg beyond its limit.")
            .arg(loc.toString(static_cast<qulonglong>(i)))
            .arg(revolution(i))
            .arg(loc.toString(-k->checks[i].limitMarginDeg, 'f', 1));
      },
      QObject::tr("... and %1 more point(s) beyond an axis limit (see the joint chart)."));
  lister(
      colliding,
      [&](size_t i) {
        return QObject::tr("Point %1 (revolution %2): the torch or a robot link collides there.")
            .arg(loc.toString(static_cast<qulonglong>(i)))
            .arg(revolution(i));
      },
      QObject::tr("... and %1 more colliding point(s) (red on the spiral)."));
}

}  // namespace spira::ui
