#pragma once

#include <cstddef>
#include <vector>

#include "spira/path/trajectory.h"
#include "spira/scan/built_wall.h"
#include "spira/scan/point_cloud.h"
#include "spira/scan/scan_deviation.h"

namespace spira {

// The three performance indices of the FGM thesis (seed 003_abf6ea7743219370.txt, section 3.4,
// equations 3.20 to 3.24), each 1 when perfect, for WAAM with deposit-height modulation: the
// attribute is the deposited height, M* the part's surface (where the wall should end), m* the
// plan's bead tops, m and M the wall as scanned. The thesis takes errors in composition fractions;
// here each is divided by the local planned bead height h_i (the trajectory's height channel), so
// 0.92 says the error is 8 % of a bead. Below 0 (an error of more than a bead) it is 0.
//
// - Trajectory index I_t (3.20, |M* - m*(lambda)|): how far each planned point lies from the part's
//   surface, |signed distance| / h_i. The plan's own error, before anything is laid.
// - Process index I_p (3.22, |m*(lambda) - m(lambda)|): at the last bead on each generatrix, the
//   measured top's shortfall over the height planned up to it on that generatrix (the beads under it
//   and itself): the mean relative error of each bead laid there.
// - Global index I_g (3.24, |M* - M|): every scan point's signed deviation from the part's surface
//   over the height of the nearest deposited point's bead.
//
// The thesis evaluates the indices at every place of the part; here each at the points that carry
// the information (plan points, edge points, scan points), as maps and as statistics.

// 1 - |error| / bead, at least 0.
double qualityIndex(double errorMm, double beadHeightMm);

struct IndexStats {
  size_t count = 0;  // points with a value
  double mean = 0.0, min = 0.0;
  double belowNinety = 0.0;  // share of them below 0.9
};

// NaN values (a point without the index) are left out; none left gives a count of 0.
IndexStats indexStats(const std::vector<double>& values);

// I_t for each plan point before `at` (the whole plan: at = plan.size()); NaN for the points laid
// without arc or without height. `surface` is the surface the plan runs on, in the plan's frame.
std::vector<double> trajectoryIndex(const Trajectory& plan, size_t at, const MeshDistance& surface);

// I_p for each of edge.points; NaN for those the scan missed (their shortfall was interpolated).
std::vector<double> processIndex(const Trajectory& plan, const MeasuredEdge& edge);

// I_g for each scan point, from its signed deviation (scanDeviation) and the height of the nearest
// point deposited before `at`. Throws InputError when nothing was deposited before `at`.
std::vector<double> globalIndex(const Trajectory& plan, size_t at, const PointCloud& scan,
                                const std::vector<double>& deviation);

// For each scan point, the index in `plan` of the deposited point before `at` nearest to it (PCL's
// k-d tree). Throws InputError when nothing was deposited before `at`.
std::vector<size_t> nearestDeposited(const Trajectory& plan, size_t at, const PointCloud& scan);
// I_g from those: the same values as globalIndex, without searching again.
std::vector<double> globalIndex(const Trajectory& plan, const std::vector<size_t>& nearest,
                                const std::vector<double>& deviation);

// The scan's deviation seen along the path: for each plan point before `at`, the mean signed deviation
// (mm) of the scan points nearest to it; NaN where none is.
std::vector<double> deviationAlongPlan(size_t at, const std::vector<size_t>& nearest,
                                       const std::vector<double>& deviation);

}  // namespace spira
