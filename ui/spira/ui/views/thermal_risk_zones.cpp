#include "spira/ui/views/thermal_risk_zones.h"

#include <algorithm>
#include <cmath>

#include <QListWidget>
#include <QLocale>
#include <QObject>

#include "spira/document/results.h"
#include "spira/pipeline/planned_path.h"
#include "spira/ui/panels/log_panel.h"

namespace spira::ui {

namespace {

// Safe points between two risk points that still leave them in one zone: a pool flickering under
// the threshold is the same zone to a process engineer.
constexpr size_t kZoneGap = 8;

}  // namespace

std::vector<RiskZone> thermalRiskZones(const ThermalStageResult& thermal)
{
  std::vector<RiskZone> zones;
  for (size_t i = 0; i < thermal.risk.size(); ++i) {
    if (!thermal.risk[i]) continue;
    if (zones.empty() || i - zones.back().last > kZoneGap + 1) zones.push_back({i, i, 0, i});
    RiskZone& z = zones.back();
    z.last = i;
    ++z.points;
    if (thermal.bond[i] > thermal.bond[z.worst]) z.worst = i;
  }
  return zones;
}

void listThermalRiskZones(LogPanel& log, QListWidget& list, const Results& results, int pointRole,
                          int maxZones)
{
  const auto& t = results.thermal;
  const auto& report = results.reports.thermal;
  if (!t || !report) return;
  const std::shared_ptr<const Trajectory> path = processPathOf(results);
  if (!path || path->size() != t->pointCount()) return;
  const QLocale loc;
  const auto revolutionOf = [&](size_t i) { return path->points[i].revolution + 1; };
  const std::vector<RiskZone> zones = thermalRiskZones(*t);
  const size_t listed = std::min(zones.size(), static_cast<size_t>(std::max(0, maxZones)));
  if (zones.empty())
    log.info(QObject::tr("Thermal: no collapse risk (Bond number up to %1, threshold %2).")
                 .arg(loc.toString(report->maxBond, 'f', 2), loc.toString(report->bondThreshold, 'f', 1)));
  for (size_t k = 0; k < listed; ++k) {
    const RiskZone& z = zones[k];
    const double interpass = t->interpass[z.worst];
    log.warning(
        QObject::tr(
            "Collapse risk, zone %1: points %2 to %3 (revolutions %4 to %5), %6 at risk; worst at point "
            "%7: Bond number %8, pool %9 mm, interpass %10.")
            .arg(k + 1)
            .arg(loc.toString(static_cast<qulonglong>(z.first)),
                 loc.toString(static_cast<qulonglong>(z.last)))
            .arg(revolutionOf(z.first))
            .arg(revolutionOf(z.last))
            .arg(loc.toString(static_cast<qulonglong>(z.points)),
                 loc.toString(static_cast<qulonglong>(z.worst)), loc.toString(t->bond[z.worst], 'f', 2),
                 loc.toString(t->poolLength[z.worst], 'f', 1),
                 std::isfinite(interpass) ? loc.toString(interpass, 'f', 0) + QStringLiteral(" °C")
                                          : QObject::tr("none")),
        QObject::tr(
            "Click to select the worst point and chart its temperature; colour the spiral by collapse "
            "risk to see the zone."));
    list.item(list.count() - 1)->setData(pointRole, static_cast<long long>(z.worst));
  }
  if (zones.size() > listed)
    log.info(QObject::tr(
                 "... and %1 more collapse-risk zone(s) (red when the spiral is coloured by collapse risk).")
                 .arg(loc.toString(static_cast<qulonglong>(zones.size() - listed))));
  if (report->interpassLimit > 0.0 && report->pointsOverLimit > 0) {
    size_t hottest = 0;
    for (size_t i = 0; i < t->pointCount(); ++i)
      if (std::isfinite(t->interpass[i]) && !(t->interpass[i] <= t->interpass[hottest])) hottest = i;
    log.warning(
        QObject::tr("Interpass temperature above the %1 °C limit at %2 point(s), up to %3 °C at point %4 "
                    "(revolution %5).")
            .arg(loc.toString(report->interpassLimit, 'f', 0),
                 loc.toString(static_cast<qlonglong>(report->pointsOverLimit)),
                 loc.toString(report->maxInterpass, 'f', 0), loc.toString(static_cast<qulonglong>(hottest)))
            .arg(revolutionOf(hottest)),
        QObject::tr(
            "Click to select the point. The Plan dock's Thermal tab holds the limit and the re-planning "
            "remedies."));
    list.item(list.count() - 1)->setData(pointRole, static_cast<long long>(hottest));
  }
}

}  // namespace spira::ui
