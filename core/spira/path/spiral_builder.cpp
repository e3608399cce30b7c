#include "spira/path/spiral_builder.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <utility>

#include "spira/base/error.h"
#include "spira/path/arc_length_polyline.h"
#include "spira/path/feasibility.h"
#include "spira/path/layer_count.h"
#include "spira/path/seam_placement.h"
#include "spira/path/spiral_frames.h"
#include "spira/path/spiral_input.h"
#include "spira/path/startup_profile.h"
#include "spira/path/too_short_error.h"

namespace spira {

namespace {

// Arc-length position of every point, revolution-major: s[k * n + i].
struct Layout {
  int n = 0;
  int revolutions = 0;
  std::vector<double> s;
};

// Ramp steps are nominal deposits, but the true height is the step times cos(theta), theta the
// angle between the generatrix and the build direction (000_dbb97c2716e10cc3.txt §3.3.4). Where the layers
// lean on the generatrices (a tilted or non-planar base such as a branch's saddle cut, a non-planar upper
// edge, a converging dome) a ramp step of h_min would lay less than h_min. Each ramp point therefore gets its
// own stretch 1 / cos(theta), per generatrix AND per revolution: the lean is largest on the revolutions next
// to the leaning edge and fades away from it, so one factor per generatrix (the largest) over-stretches the
// revolutions that do not lean, and the surplus climb, different from one generatrix to the next, leaves a
// step in the layer that the modulated phase carries up (000_dbb97c2716e10cc3.txt §3.2.4: the start-up must
// remove a height step, not make one). See stretchSteps(). The modulated revolutions get the same per-point
// stretch, normalised along each generatrix so that they still share its modulated length: a generatrix whose
// layers lean on some revolutions (an arm's first layers above its saddle cut) lays longer steps there and
// shorter ones where they do not, every layer of it at the one true height its length allows.
struct StepScales {
  int n = 0;
  int layers = 0;                       // modulated revolutions `mod` was measured on
  std::vector<double> start, end, mod;  // [r * n + i]: revolution r of the phase, generatrix i
  StepScales(int points, int startRevs, int endRevs)
      : n(points),
        start(static_cast<size_t>(startRevs) * points, 1.0),
        end(static_cast<size_t>(endRevs) * points, 1.0)
  {
  }
  double startAt(int r, int i) const { return start[static_cast<size_t>(r) * n + i]; }
  double endAt(int r, int i) const { return end[static_cast<size_t>(r) * n + i]; }
  // Modulated revolution m's share of generatrix i's modulated length, nLayers shares in all.
  std::vector<double> modShares(int i, int nLayers) const
  {
    std::vector<double> share(static_cast<size_t>(nLayers), 1.0);
    if (layers != nLayers) return share;
    double sum = 0.0;
    for (int m = 0; m < nLayers; ++m) sum += share[m] = mod[static_cast<size_t>(m) * n + i];
    for (double& x : share) x *= nLayers / sum;
    return share;
  }
};

// Stretched length of the start-up and of the termination on generatrix i.
double startLength(const StartupProfile& p, const StepScales& sc, int i, double u)
{
  double sum = 0.0;
  for (int r = 0; r < p.startRevolutions(); ++r) sum += p.startStep(r, u) * sc.startAt(r, i);
  return sum;
}

double endLength(const StartupProfile& p, const StepScales& sc, int i, double u)
{
  double sum = 0.0;
  for (int r = 0; r < p.endRevolutions(); ++r) sum += p.endStep(r, u) * sc.endAt(r, i);
  return sum;
}

void throwTooShort(size_t i, double length, double ramps, double hMin)
{
  std::ostringstream m;
  m << "generatrix " << i << " is " << length << " mm long, but the start-up and termination ramps take "
    << ramps << " mm of it and the modulated phase needs at least h_min = " << hMin << " mm more";
  throw TooShortError(m.str(),
                      "use a smaller h or a wider window (fewer start-up revolutions), or a taller part",
                      length, ramps + hMin);
}

// Ramps and layer count. With StartupTransition::UniformHelix the ramps are sized for the layer
// step c the modulated phase uses at the seam (the mean step of the first and last generatrices),
// which depends on the layer count, which depends on the length the ramps take. For a given count
// c solves c n_layer = (l_0(c) + l_{n-1}(c)) / 2, monotone in c (bisection over the window); the
// count is then recomputed, until both agree (a few rounds at most).
// `scale` stretches the ramp steps of each generatrix (see StepScales).
Layout layOut(const std::vector<double>& lengths, const SpiralSettings& s, const StepScales& scale,
              StartupProfile& prof, SpiralReport& report)
{
  const int n = static_cast<int>(lengths.size());
  const bool ramps = s.termination == Termination::Ramps;
  std::vector<double> startLen(n), modLen(n);
  const auto rampLength = [&](const StartupProfile& p, int i) {
    const double u = static_cast<double>(i) / (n - 1);
    return startLength(p, scale, i, u) + (ramps ? endLength(p, scale, i, u) : 0.0);
  };
  // Lays the ramps for seam step c (0: h); returns the layer count they leave room for.
  const auto measure = [&](double c) {
    prof = StartupProfile(s.h, s.hMin, s.hMax, s.startupTransition, n, c);
    for (int i = 0; i < n; ++i) {
      startLen[i] = startLength(prof, scale, i, static_cast<double>(i) / (n - 1));
      modLen[i] = lengths[i] - rampLength(prof, i);
      if (modLen[i] < s.hMin * (1.0 - 1e-9)) throwTooShort(i, lengths[i], lengths[i] - modLen[i], s.hMin);
    }
    const int count = countLayers(modLen, s.h, s.hMin, s.hMax, s.layerMode);
    if (count < 1) throwTooShort(0, lengths[0], lengths[0] - modLen[0], s.hMin);
    return count;
  };
  const auto seamExcess = [&](double c, int count) {
    const StartupProfile p(s.h, s.hMin, s.hMax, s.startupTransition, n, c);
    return c * count - 0.5 * (lengths[0] - rampLength(p, 0) + lengths[n - 1] - rampLength(p, n - 1));
  };

  int nLayers = measure(0.0);
  for (int round = 0; round < 10 && s.startupTransition == StartupTransition::UniformHelix; ++round) {
    double lo = s.hMin, hi = s.hMax;
    if (seamExcess(lo, nLayers) >= 0.0) {
      hi = lo;
    } else if (seamExcess(hi, nLayers) <= 0.0) {
      lo = hi;
    }
    for (int it = 0; it < 60 && hi - lo > 1e-13 * s.h; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (seamExcess(mid, nLayers) < 0.0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    const int count = measure(0.5 * (lo + hi));
    if (count == nLayers) break;
    nLayers = count;
  }

  report.nStartupRevolutions = prof.startRevolutions();
  report.nLayers = nLayers;
  report.nEndRevolutions = ramps ? prof.endRevolutions() : 0;
  report.nRevolutions = report.nStartupRevolutions + nLayers + report.nEndRevolutions;
  report.lengthCriterion = lengthCriterion(modLen, nLayers, s.hMin, s.hMax);
  report.thesisLengthCriterion = thesisLengthCriterion(lengths, s.hMin, s.hMax);
  const auto [gMin, gMax] = std::minmax_element(lengths.begin(), lengths.end());
  report.generatrixLengthMin = *gMin;
  report.generatrixLengthMax = *gMax;
  report.modulatedLengthMin = report.lengthCriterion.lengthMin;
  report.modulatedLengthMax = report.lengthCriterion.lengthMax;
  report.stepMin = report.modulatedLengthMin / nLayers;
  report.stepMax = report.modulatedLengthMax / nLayers;
  report.seamStep = modLen[0] / nLayers - prof.climb();

  Layout lay;
  lay.n = n;
  lay.revolutions = report.nRevolutions;
  lay.s.resize(static_cast<size_t>(lay.revolutions) * n);
  for (int i = 0; i < n; ++i) {
    const double u = static_cast<double>(i) / (n - 1);
    const double d = modLen[i] / nLayers;
    const std::vector<double> share = scale.modShares(i, nLayers);
    int k = 0;
    double acc = 0.0;
    for (int r = 0; r < report.nStartupRevolutions; ++r, ++k)
      lay.s[k * n + i] = acc += prof.startStep(r, u) * scale.startAt(r, i);
    double climbed = 0.0;
    for (int m = 1; m <= nLayers; ++m, ++k) {
      climbed += share[m - 1];
      lay.s[k * n + i] = acc = startLen[i] + (m == nLayers ? modLen[i] : climbed * d);
    }
    for (int r = 0; r < report.nEndRevolutions; ++r, ++k)
      lay.s[k * n + i] = acc += prof.endStep(r, u) * scale.endAt(r, i);
    lay.s[(lay.revolutions - 1) * n + i] = lengths[i];  // exactly on the edge, whatever the rounding
  }
  return lay;
}

// Number of trailing revolutions shorter than minLength; at least the last one is kept out, since
// on a closed part it is the closure point repeated. The first revolution always stays.
int trailingDegenerate(const Trajectory& path, int n, int revolutions, double minLength)
{
  int collapsed = 1;
  for (int k = revolutions - 2; k >= 1; --k, ++collapsed) {
    double perimeter = 0.0;
    const auto* rev = &path.points[static_cast<size_t>(k) * n];
    for (int i = 1; i < n; ++i) perimeter += (rev[i].position - rev[i - 1].position).norm();
    if (perimeter >= minLength) break;
  }
  return collapsed;
}

// One layout and sampling of the spiral with the given ramp scales.
SpiralResult buildPass(const Generatrices& g, const std::vector<ArcLengthPolyline>& arcs,
                       const std::vector<double>& lengths, const SpiralSettings& settings,
                       const StepScales& scales, std::vector<double>& cosines, Progress& progress)
{
  const int n = static_cast<int>(g.lines.size());
  StartupProfile prof(settings.h, settings.hMin, settings.hMax);
  SpiralResult result;
  SpiralReport& report = result.report;
  report.pointsPerRevolution = n;
  const Layout lay = layOut(lengths, settings, scales, prof, report);
  const int revs = lay.revolutions;

  // Generatrix by generatrix, so each polyline is swept once while it is in cache; points are
  // stored revolution by revolution, the spiral order.
  Trajectory& path = result.trajectory;
  path.points.resize(lay.s.size());
  for (int i = 0; i < n; ++i) {
    progress.checkCancel();
    size_t cursor = 0;
    for (int k = 0; k < revs; ++k) {
      const size_t q = static_cast<size_t>(k) * n + i;
      const auto sample = arcs[i].at(lay.s[q], cursor);
      TrajectoryPoint& p = path.points[q];
      p.position = sample.position;
      p.normal = sample.normal;
      p.revolution = k;
      p.generatrix = i;
      p.arcOn = true;
    }
    if (i % 64 == 0) progress.report(0.7 * i / n, "spiral");
  }

  const double minRev = settings.minRevolutionLength > 0.0 ? settings.minRevolutionLength : settings.h;
  report.collapsedRevolutions = g.hasClosurePoint ? trailingDegenerate(path, n, revs, minRev) : 0;
  const int kept = revs - report.collapsedRevolutions;
  const bool closure = report.collapsedRevolutions > 0;
  path.points.resize(static_cast<size_t>(kept) * n);
  if (closure) {
    TrajectoryPoint p;
    p.position = g.closurePoint;
    p.normal = arcs[0].at(lengths[0]).normal;
    p.revolution = kept;
    p.generatrix = 0;
    p.arcOn = true;
    path.points.push_back(p);
  }

  // Generatrix step vector (from the same generatrix one revolution below, or its base) and arc
  // step of every point; the closure point steps from generatrix 0.
  const size_t count = path.points.size();
  std::vector<Vec3> steps(count);
  std::vector<double> arcSteps(count);
  for (size_t q = 0; q < static_cast<size_t>(kept) * n; ++q) {
    const bool first = q < static_cast<size_t>(n);
    const Vec3& below = first ? g.lines[q].front() : path.points[q - n].position;
    steps[q] = path.points[q].position - below;
    arcSteps[q] = lay.s[q] - (first ? 0.0 : lay.s[q - n]);
  }
  if (closure) {
    const size_t below = static_cast<size_t>(kept - 1) * n;  // generatrix 0, last kept revolution
    steps.back() = g.closurePoint - path.points[below].position;
    arcSteps.back() = lengths[0] - lay.s[below];
  }
  progress.report(0.8, "spiral frames");

  computeFrames(path);
  report.normalsFlipped = orientBuildDirection(path, steps);
  if (closure && count > 1) {
    // The pole has no build direction of its own (every generatrix ends there): the torch keeps the
    // last ring's orientation as it steps to the centre.
    TrajectoryPoint& c = path.points.back();
    const TrajectoryPoint& last = path.points[count - 2];
    c.normal = last.normal;
    c.tangent = last.tangent;
    c.build = last.build;
  }
  computeDepositHeights(path, steps, std::min(count, static_cast<size_t>(n)));
  cosines.assign(count, 1.0);
  for (size_t q = 0; q < count; ++q)
    if (arcSteps[q] > 0.0) cosines[q] = path.points[q].height / arcSteps[q];
  if (closure) {
    report.closureGap = arcSteps.back();
    path.points.back().height = path.points[count - 2].height;
  }
  checkFeasibility(path, settings.h, settings.hMin, settings.hMax, settings.heightTolerance, closure, report);

  report.nPoints = count;
  report.pathLength = path.length();
  for (size_t q = 1; q < count; ++q) {
    const TrajectoryPoint& a = path.points[q - 1];
    const TrajectoryPoint& b = path.points[q];
    report.maxJump = std::max(report.maxJump, (b.position - a.position).norm());
    if (a.revolution != b.revolution)
      report.seamRiseMax = std::max(report.seamRiseMax, (b.position - a.position).dot(a.build));
  }
  return result;
}

// Ramp scales are smoothed and limited along each revolution, from its first generatrix to its
// last, and never across its seam. Nothing couples a revolution's last point to the next one's
// first: the seam point takes its travel direction from the chord before it (computeFrames), and
// the ramp step jumps there (h_max on the last generatrix, h_min on the next revolution's first), so
// where the lean changes with height the lean a step crosses jumps with it. Nor is a revolution's
// last point a neighbour of its own first, a whole ramp climb (1.6 mm at +-10 %) below it. On a
// tube whose wall starts leaning 19 degrees at z = 6.2 mm, the fourth full ramp needs a stretch of
// 1.02 on its first generatrices and 1.07 on its last: a limit closed around the revolution would
// hold the last ones to 1.04 (the path dips 0.05 mm before the seam, its travel direction falls 10
// degrees and the bead measured along the tilted build direction grows to 2.235 mm), and smoothing
// across the seam would pull the first ones towards the previous revolution's last (1.0, below
// the bend).

// Neighbouring generatrices' scales on one ramp revolution may differ by at most `limit`; a scale
// is lowered towards its neighbour, never raised above its own target.
void limitNeighbours(double* row, int n, double limit)
{
  for (int i = 1; i < n; ++i) row[i] = std::min(row[i], row[i - 1] + limit);
  for (int i = n - 2; i >= 0; --i) row[i] = std::min(row[i], row[i + 1] + limit);
}

// Smooths one ramp revolution's scales along the deposited path with passes of the binomial
// filter 1/4, 1/2, 1/4 (the ends repeat themselves). The true height of a point is measured in its
// frame, whose travel direction is the chord to the next point, so a point stretched more than its
// neighbours tilts the chords on both sides of it and lowers their heights, which the next
// iteration answers by stretching them, and the neighbour after lower: an alternating pattern
// (neighbouring points 0.1-0.4 mm up and down, 0.5 mm apart on a branch's arm next to the crotch)
// grows from the point-by-point fixed point. The filter removes that pattern (the 1/4, 1/2, 1/4
// filter maps it to zero) and any variation over fewer than a few points, which a deposit cannot
// follow anyway; a constant stretch (an unleaning part: all 1) is left exactly.
void smoothAlongPath(double* row, int n, int passes)
{
  if (n < 3) return;
  std::vector<double> out(static_cast<size_t>(n));
  for (int p = 0; p < passes; ++p) {
    for (int i = 0; i < n; ++i)
      out[i] = 0.25 * (row[std::max(i - 1, 0)] + 2.0 * row[i] + row[std::min(i + 1, n - 1)]);
    std::copy(out.begin(), out.end(), row);
  }
}

// Where a generatrix's scales hardly change over the ramp revolutions (by less than `flat`: the
// heights within 0.1 %), they all take the largest. Per-revolution scales that differ by such
// noise still break the design's ramp lengths (start plus end the same on every generatrix) by a
// little that differs from one generatrix to the next, and close to a pole, where neighbours are
// fractions of a millimetre apart, that little tilts the layers (docs/method.md M18) more than it gains.
void flattenNearlyUniform(std::vector<double>& scales, int n, double flat)
{
  const size_t revs = scales.size() / static_cast<size_t>(n);
  for (int i = 0; i < n; ++i) {
    double lo = scales[static_cast<size_t>(i)], hi = lo;
    for (size_t r = 1; r < revs; ++r) {
      lo = std::min(lo, scales[r * n + i]);
      hi = std::max(hi, scales[r * n + i]);
    }
    if (hi - lo < flat)
      for (size_t r = 0; r < revs; ++r) scales[r * n + i] = hi;
  }
}

// One step of the ramp stretch's fixed-point iteration (see StepScales). Each ramp point's target
// scale is 1 / cos(theta) measured on `pass`, the layout built with the current scales, so that its
// true height (nominal step x scale x cos(theta), docs/method.md M18) is the nominal one. Stretching a point
// moves it along its generatrix, which turns its layer and changes theta, so the iteration is
// damped (the scales move half-way to their targets), smoothed along the revolution
// (smoothAlongPath, kSmoothPasses: on the Y tube's arms this took the rows outside the window from
// 130 and 146 to 25 and 28) and kept smooth along each revolution (limitNeighbours), neither across
// the seam (see above). Without that limit, generatrices whose lean changes abruptly (a branch's
// arm on its tilted saddle cut) stretch one side of a revolution far more than the other, the step
// between them turns the layer nearly parallel to the generatrices, theta grows and the iteration
// runs away. The stretch is capped at kMaxStretch (theta = 60 degrees); it falls below 1 only on a
// first ring that leans at its base, measured from the plane it rests on (computeDepositHeights),
// where the chord runs steeper than b. Stretches within
// kStretchFloor of 1 (the height within 0.01 % of nominal) are left at 1, so a part whose layers do
// not lean keeps exactly the designed layout. Returns the largest change of a scale.
// How smooth a revolution's scales must be depends on how far apart its points are, not on how
// many there are: a difference ds between neighbours `spacing` apart tilts the ring by about
// ds h / spacing, and the smoothing should reach about h / 2 along the path. The limit 0.03 and 4
// passes suit points 0.7 mm apart (120 round the Y tube's arm, h = 2 mm); on the same arm at 360
// points they let the ring wobble by up to 0.2 mm from one point to the next, tilting b by up to 20
// degrees between neighbours and planning heights down to 0.86 mm. Denser revolutions get a limit
// and passes that keep the tilt and the reach in mm; sparser ones keep 0.03 and 4.
struct RowSmoothing {
  double limit;
  int passes;
};
RowSmoothing rowSmoothing(const Trajectory& path, int revolution, int n, double h)
{
  constexpr double kNeighbourStretch = 0.03, kRingTilt = 0.085;
  constexpr int kSmoothPasses = 4, kMostPasses = 64;
  const size_t first = static_cast<size_t>(revolution) * static_cast<size_t>(n);
  if (n < 2 || first + static_cast<size_t>(n) > path.size()) return {kNeighbourStretch, kSmoothPasses};
  double length = 0.0;
  for (size_t q = first + 1; q < first + static_cast<size_t>(n); ++q)
    length += (path.points[q].position - path.points[q - 1].position).norm();
  const double spacing = length / (n - 1);
  if (!(spacing > 0.0)) return {kNeighbourStretch, kMostPasses};
  // p passes of the 1/4, 1/2, 1/4 filter spread over sqrt(p / 2) points.
  const double reach = 0.5 * h / spacing;
  const int passes = static_cast<int>(std::min<double>(kMostPasses, std::ceil(2.0 * reach * reach)));
  return {std::min(kNeighbourStretch, kRingTilt * spacing / h), std::max(kSmoothPasses, passes)};
}

double stretchSteps(const SpiralResult& pass, const std::vector<double>& cosines, double h,
                    StepScales& scales)
{
  constexpr double kStretchFloor = 1e-4;
  constexpr double kRelax = 0.5;
  constexpr double kFlatStretch = 1e-3;
  constexpr double kMaxStretch = 2.0;
  const SpiralReport& rep = pass.report;
  const auto& pts = pass.trajectory.points;
  const size_t last = rep.collapsedRevolutions > 0 ? pts.size() - 1 : pts.size();
  const int endFirst = rep.nStartupRevolutions + rep.nLayers;
  const int n = scales.n;
  if (scales.layers != rep.nLayers) {
    scales.layers = rep.nLayers;
    scales.mod.assign(static_cast<size_t>(rep.nLayers) * n, 1.0);
  }
  StepScales next = scales;
  for (size_t q = 0; q < last; ++q) {
    const TrajectoryPoint& p = pts[q];
    if (cosines[q] <= 0.0) continue;
    const SpiralPhase phase = phaseOfRevolution(p.revolution, rep);
    const bool start = phase == SpiralPhase::StartUp, mod = phase == SpiralPhase::Modulated;
    const int r = p.revolution - (start ? 0 : mod ? rep.nStartupRevolutions : endFirst);
    const size_t at = static_cast<size_t>(r) * n + p.generatrix;
    double stretch = std::min(1.0 / cosines[q], kMaxStretch);
    if (std::abs(stretch - 1.0) <= kStretchFloor) stretch = 1.0;
    std::vector<double>& to = start ? next.start : mod ? next.mod : next.end;
    const double old = (start ? scales.start : mod ? scales.mod : scales.end)[at];
    to[at] = old + kRelax * (stretch - old);
  }
  double change = 0.0;
  for (auto [now, was, firstRev] :
       {std::tuple(&next.start, &scales.start, 0), std::tuple(&next.end, &scales.end, endFirst),
        std::tuple(&next.mod, &scales.mod, rep.nStartupRevolutions)}) {
    for (size_t r = 0; r * n < now->size(); ++r) {
      const RowSmoothing row = rowSmoothing(pass.trajectory, firstRev + static_cast<int>(r), n, h);
      smoothAlongPath(now->data() + r * n, n, row.passes);
      limitNeighbours(now->data() + r * n, n, row.limit);
    }
    flattenNearlyUniform(*now, n, kFlatStretch);
    for (size_t k = 0; k < now->size(); ++k) change = std::max(change, std::abs((*now)[k] - (*was)[k]));
  }
  scales = std::move(next);
  return change;
}

}  // namespace

SpiralResult buildSpiral(const Generatrices& generatrices, const SpiralSettings& settings, Progress& progress)
{
  StartupProfile prof(settings.h, settings.hMin, settings.hMax);  // window errors before geometry errors
  validateSpiralSettings(settings);
  progress.report(0.0, "spiral");
  const PreparedGeneratrices prep = prepareGeneratrices(generatrices, settings);
  const int seam = leastLeaningSeam(prep.generatrices(), (prof.startRevolutions() + 1) * settings.h);
  const Generatrices reindexed = seam != 0 ? startingAt(prep.generatrices(), seam) : Generatrices{};
  const Generatrices& g = seam != 0 ? reindexed : prep.generatrices();
  const int n = static_cast<int>(g.lines.size());

  std::vector<ArcLengthPolyline> arcs;
  arcs.reserve(n);
  std::vector<double> lengths(n);
  for (int i = 0; i < n; ++i) {
    arcs.emplace_back(g.lines[i], g.normals[i]);
    lengths[i] = arcs[i].length();
  }

  // The stretch is a fixed point: stretching a ramp point moves it, which turns its layer and so
  // changes the theta it is measured with. A few passes settle it (the change shrinks roughly
  // geometrically); the pass with the fewest window violations is kept (the later on a tie), so a
  // stretch that does not settle can never make the spiral worse than the unstretched layout.
  constexpr int kMaxPasses = 12;
  constexpr double kSettled = 1e-4;
  const int rampRevs = prof.startRevolutions();
  StepScales scales(n, rampRevs, rampRevs);
  std::vector<double> cosines;
  SpiralResult result = buildPass(g, arcs, lengths, settings, scales, cosines, progress);
  SpiralResult best;
  bool stretched = false;
  for (int pass = 1; pass < kMaxPasses; ++pass) {
    if (stretchSteps(result, cosines, settings.h, scales) <= kSettled) break;
    SpiralResult next;
    try {
      next = buildPass(g, arcs, lengths, settings, scales, cosines, progress);
    } catch (const InputError&) {
      break;  // the stretched ramps no longer fit on a short generatrix: keep the layouts that did
    }
    if (!stretched || result.report.violations.size() < best.report.violations.size())
      best = std::move(result);
    stretched = true;
    result = std::move(next);
  }
  if (stretched && best.report.violations.size() < result.report.violations.size()) result = std::move(best);
  result.report.normalsEstimated = prep.normalsEstimated();
  // Points and violations keep the decomposer's generatrix numbers.
  for (TrajectoryPoint& p : result.trajectory.points) p.generatrix = (p.generatrix + seam) % n;
  for (HeightViolation& v : result.report.violations) v.generatrix = (v.generatrix + seam) % n;
  progress.report(1.0, "spiral");
  return result;
}

}  // namespace spira
