#include "geodesic_decomposition.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "base_ring.h"
#include "coverage.h"
#include "generatrix_solver.h"
#include "length_spread.h"
#include "merged_neighbours.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/field/heat_distance.h"
#include "surface_locator.h"

namespace spira::geodesic {

namespace {

constexpr size_t kBatch = 32;  // generatrices between progress reports

double secondsSince(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

SurfacePoint pointAtVertex(const GeodesicMesh& gm, int v)
{
  const int corner = *gm.cornersBegin(v);
  Vec3 bary = Vec3::Zero();
  bary[corner % 3] = 1.0;
  return gm.pointOn(corner / 3, bary);
}

// The closed part's closure point: the finder's, or the vertex farthest from the base.
SurfacePoint findClosure(const GeodesicMesh& gm, const SurfaceLocator& locator, HeatDistanceSolver& heat,
                         const BoundaryLoop& lower, const std::optional<Vec3>& closurePoint,
                         const std::vector<double>* baseDistance, Progress& progress)
{
  if (closurePoint) return locator.closest(*closurePoint);
  std::vector<double> computed;
  if (!baseDistance || baseDistance->size() != gm.mesh().vertexCount()) {
    computed = heat.compute(lower.vertices, progress);
    baseDistance = &computed;
  }
  int far = -1;
  for (size_t v = 0; v < baseDistance->size(); ++v) {
    const double d = (*baseDistance)[v];
    if (std::isfinite(d) && gm.cornersBegin(int(v)) != gm.cornersEnd(int(v)) &&
        (far < 0 || d > (*baseDistance)[size_t(far)]))
      far = int(v);
  }
  if (far < 0) throw InputError("the part has no vertex reachable from its lower edge", "repair the mesh");
  return pointAtVertex(gm, far);
}

GeneratrixLine lineFromPath(const GeodesicMesh& gm, const SolvedGeneratrix& s, const BasePoint& base)
{
  GeneratrixLine line;
  line.angle = base.angle;
  line.exactLength = s.path.length;
  line.points.reserve(s.path.points.size());
  line.normals.reserve(s.path.points.size());
  for (const PathPoint& p : s.path.points) {
    line.points.push_back(p.position);
    line.normals.push_back(gm.normalAt(p.vertices.data(), p.weights, 3));
  }
  // The path's own ends may sit a rounding error away (see SubmeshGeodesics): use the exact ones,
  // so every line starts on the lower edge and, on closed parts, ends on the very same point.
  line.points.front() = base.point.position;
  line.points.back() = s.end.position;
  return line;
}

// Two neighbouring generatrices closer than 1 % of the spacing they started at (or of a bead)
// have met. There one revolution's step from one to the other is a hundredth of its usual length,
// so its direction, and the bead height d cos(theta) the spiral lays along it, is set by the
// difference of their heights: on a waisted vase of revolution the bead where two of them pass a
// saddle vertex on either side thins to a fifth (0.38 mm for 2 mm). Where they share a track the
// spiral steps up the wall instead of round it and leaves the surface beside them to the next
// neighbour. Checked batch by batch as the exact paths come in, so such a part is refused without
// waiting for the rest of its searches: any pair refuses, the count reported is of the pairs
// checked so far.
class MeetingNeighboursCheck {
 public:
  MeetingNeighboursCheck(const std::vector<BasePoint>& bases, const GeodesicOptions& options,
                         const std::optional<Vec3>& closure)
      : beadWidth_(options.beadWidth), closure_(closure), lines_(bases.size())
  {
    double spacing = 0.0;
    for (size_t i = 0; i < bases.size(); ++i)
      spacing += (bases[(i + 1) % bases.size()].point.position - bases[i].point.position).norm();
    spacing /= double(std::max<size_t>(bases.size(), 1));
    gap_ = 0.01 * std::min(beadWidth_, spacing);
  }

  // Takes the paths of lines [begin, end) and checks every pair whose two lines are now known.
  void add(const std::vector<SolvedGeneratrix>& solved, size_t begin, size_t end)
  {
    const size_t n = lines_.size();
    if (!(beadWidth_ > 0.0) || n < 2) return;
    for (size_t i = begin; i < end; ++i) {
      Polyline& line = lines_[i];
      line.clear();
      for (const PathPoint& p : solved[i].path.points) line.push_back(p.position);
    }
    const size_t upTo = end == n ? n : end - 1;
    const MergedNeighbours m = findMergedNeighbours(lines_, checked_, upTo, gap_, 0.0, closure_, beadWidth_);
    if (m.pairs) refuse(m, upTo);
    checked_ = upTo;
  }

 private:
  [[noreturn]] void refuse(const MergedNeighbours& m, size_t checkedPairs) const
  {
    const size_t n = lines_.size();
    static const char* const why =
        " on. Shortest paths on this mesh bend round or through the same vertices (the saddles of a waist or "
        "of its facets); where two meet, the spiral steps up the wall instead of round it, laying beads far "
        "thinner than the window, under earlier ones or in mid-air, and fill-in generatrices (medians of the "
        "two) cannot part them";
    std::ostringstream what;
    what << "neighbouring geodesic generatrices meet: " << m.pairs << " of the first " << checkedPairs
         << " neighbouring pairs (of " << n << ") come within " << significantText(gap_, 2)
         << " mm of each other (1 % of their spacing at the base); the longest stretch, from the base "
         << "points at " << pointText(lines_[m.first].front(), 1) << " and "
         << pointText(lines_[(m.first + 1) % n].front(), 1) << ", is " << significantText(m.stretch, 3)
         << " mm from " << pointText(m.from, 1) << why;
    throw InputError(what.str(),
                     "use --strategy isovalue: its generatrices follow a field's gradient and do not meet");
  }

  double beadWidth_ = 0.0, gap_ = 0.0;
  std::optional<Vec3> closure_;
  std::vector<Polyline> lines_;
  size_t checked_ = 0;  // pairs [0, checked_) passed
};

// The target the generatrices run to (the upper edge, or the closure point and its nearest
// vertex) and the vertices the guide field is the distance from.
GeodesicTarget findTarget(const GeodesicMesh& gm, const SurfaceLocator& locator, HeatDistanceSolver& heat,
                          const BoundaryLoop& lower, const BoundaryLoop* upper,
                          const std::optional<Vec3>& closurePoint, const std::vector<double>* baseDistance,
                          std::vector<int>& guideSources, Progress& progress)
{
  const TriangleMesh& mesh = gm.mesh();
  GeodesicTarget target;
  if (upper) {
    target.upper = upper;
    target.upperIndex.assign(mesh.vertexCount(), -1);
    target.upperVertex.assign(mesh.vertexCount(), 0);
    for (size_t i = 0; i < upper->vertices.size(); ++i) {
      target.upperIndex[size_t(upper->vertices[i])] = int(i);
      target.upperVertex[size_t(upper->vertices[i])] = 1;
    }
    guideSources = upper->vertices;
  } else {
    SubProgress closureProgress(progress, 0.1, 0.15, "closure point");
    target.closure = findClosure(gm, locator, heat, lower, closurePoint, baseDistance, closureProgress);
    const Face& cf = mesh.faces[size_t(target.closure.face)];
    int k = 0;
    for (int j = 1; j < 3; ++j)
      if (target.closure.bary[j] > target.closure.bary[k]) k = j;
    target.closureVertex = cf[size_t(k)];
    guideSources = {target.closureVertex};
  }
  return target;
}

void requireBasesReachTarget(const TriangleMesh& mesh, const std::vector<BasePoint>& bases,
                             const std::vector<double>& guide, bool open)
{
  for (const BasePoint& b : bases)
    for (int v : mesh.faces[size_t(b.point.face)])
      if (!std::isfinite(guide[size_t(v)])) {
        std::ostringstream where;
        where.precision(4);
        where << "(" << b.point.position.x() << ", " << b.point.position.y() << ", " << b.point.position.z()
              << ")";
        throw InputError("no path on the surface joins the base point at " + where.str() + " to the " +
                             (open ? "upper edge" : "closure point"),
                         "the part must be one connected surface from its lower edge to its top: check the "
                         "mesh for gaps or separate pieces");
      }
}

// The exact geodesics, in parallel: each thread keeps its own band scratch, each search its own
// shortest-path tree over the shared, read-only mesh. Batch by batch, so that meeting neighbours
// refuse the part early.
std::vector<SolvedGeneratrix> solveGeneratrices(const GeodesicMesh& gm, const std::vector<double>& guide,
                                                const GeodesicTarget& target,
                                                const std::vector<BasePoint>& bases,
                                                const GeodesicOptions& options, Progress& progress)
{
  const size_t n = bases.size();
  const GeneratrixSolver solver(gm, guide, target);
  tbb::enumerable_thread_specific<Corridor> bands([&gm] { return Corridor(gm); });
  std::vector<SolvedGeneratrix> solved(n);
  MeetingNeighboursCheck meeting(bases, options,
                                 target.open() ? std::nullopt : std::optional<Vec3>(target.closure.position));
  for (size_t begin = 0; begin < n; begin += kBatch) {
    const size_t end = std::min(n, begin + kBatch);
    tbb::parallel_for(begin, end, [&](size_t i) {
      progress.checkCancel();
      solved[i] = solver.solve(bases[i].point, bands.local(), progress);
    });
    progress.checkCancel();
    meeting.add(solved, begin, end);
    progress.report(0.2 + 0.65 * double(end) / double(n), "geodesics");
  }
  return solved;
}

// The searches' figures into `stats`; returns the mean exact length.
double recordSearches(const std::vector<SolvedGeneratrix>& solved, GeodesicStats& stats)
{
  const size_t n = solved.size();
  stats.geodesics = n;
  double bandFaces = 0.0, meanLength = 0.0;
  for (const SolvedGeneratrix& s : solved) {
    stats.untraced += s.traced ? 0 : 1;
    stats.widened += s.rings > 1 || s.rings < 0 ? 1 : 0;
    stats.wholeMesh += s.rings < 0 ? 1 : 0;
    bandFaces += double(s.bandFaces);
    meanLength += s.path.length;
  }
  stats.meanBandFaces = bandFaces / double(n);
  return meanLength / double(n);
}

// One point count for all: the spacing asked for along the mean generatrix.
std::vector<GeneratrixLine> resampleLines(const GeodesicMesh& gm, const std::vector<SolvedGeneratrix>& solved,
                                          const std::vector<BasePoint>& bases, size_t samples)
{
  std::vector<GeneratrixLine> lines(solved.size());
  tbb::parallel_for(size_t(0), solved.size(), [&](size_t i) {
    lines[i] = resampleLine(lineFromPath(gm, solved[i], bases[i]), samples);
  });
  return lines;
}

void warnAboutBaseAndCoverage(size_t ambiguous, size_t n, const CoverageResult& coverage,
                              const GeodesicOptions& options, std::vector<std::string>& warnings)
{
  if (ambiguous)
    warnings.push_back("the lower edge is not star-shaped about its centroid: at " +
                       std::to_string(ambiguous) + " of " + std::to_string(n) +
                       " angles the vertical half-plane crosses it several times and the outermost crossing "
                       "was used; the generatrices there may start out of order");
  if (coverage.fillIns)
    warnings.push_back("coverage (thesis Eq. 3.9): " + std::to_string(coverage.fillIns) +
                       " fill-in generatrices were inserted in " + std::to_string(coverage.rounds) +
                       " round(s) where neighbouring geodesics left the surface uncovered by more than " +
                       significantText(options.coverageTolerance, 3) + " mm");
  if (!coverage.converged)
    warnings.push_back("coverage error " + significantText(coverage.maxError, 3) +
                       " mm remains between generatrices " + std::to_string(coverage.worstPair) + " and " +
                       std::to_string((coverage.worstPair + 1) % coverage.lines.size()) + " (tolerance " +
                       significantText(options.coverageTolerance, 3) +
                       " mm): raise --points-per-rev or --fill-rounds, or use --strategy isovalue");
}

void storeLines(CoverageResult& coverage, const GeodesicTarget& target, GeodesicDecomposition& out)
{
  Generatrices& g = out.generatrices;
  const size_t count = coverage.lines.size();
  g.lines.resize(count);
  g.normals.resize(count);
  out.fillIn.resize(count);
  out.exactLengths.resize(count);
  for (size_t i = 0; i < count; ++i) {
    GeneratrixLine& l = coverage.lines[i];
    out.fillIn[i] = l.fillIn;
    out.exactLengths[i] = l.fillIn ? l.length() : l.exactLength;
    g.lines[i] = std::move(l.points);
    g.normals[i] = std::move(l.normals);
  }
  if (!target.open()) {
    g.hasClosurePoint = true;
    g.closurePoint = target.closure.position;
  }
}

}  // namespace

GeodesicDecomposition decomposeByGeodesics(const TriangleMesh& mesh, const BoundaryLoop& lower,
                                           const BoundaryLoop* upper, const std::optional<Vec3>& closurePoint,
                                           const std::vector<double>* baseDistance,
                                           const GeodesicOptions& options, Progress& progress)
{
  const size_t n = options.pointsPerRevolution;
  if (n < 3)
    throw InputError("the generatrix count must be at least 3, not " + std::to_string(n),
                     "raise --points-per-rev");
  if (upper && upper->vertices.size() < 3)
    throw InputError("the upper edge has fewer than 3 vertices", "repair the mesh");
  GeodesicDecomposition out;
  GeodesicStats& stats = out.stats;
  auto t0 = std::chrono::steady_clock::now();

  // Set-up: connectivity, the base, the target and an approximate distance to it (the guide).
  const GeodesicMesh gm(mesh);
  const BaseRing ring(gm, lower);
  const SurfaceLocator locator(mesh);
  SubProgress setupProgress(progress, 0.0, 0.1, "guide field");
  HeatDistanceSolver heat(mesh, HeatDistanceOptions{}, setupProgress);
  std::vector<int> guideSources;
  const GeodesicTarget target =
      findTarget(gm, locator, heat, lower, upper, closurePoint, baseDistance, guideSources, progress);
  SubProgress guideProgress(progress, 0.15, 0.2, "guide field");
  const std::vector<double> guide = heat.compute(guideSources, guideProgress);

  size_t ambiguous = 0;
  const std::vector<BasePoint> bases = ring.discretise(n, &ambiguous);
  requireBasesReachTarget(mesh, bases, guide, upper != nullptr);
  // Eq. 3.6 from bounds on the lengths: parts the window cannot hold are refused before the
  // exact searches, which cost by far the most.
  requireLengthsFitWindow(boundGeneratrixLengths(gm, bases, target), bases, options.window, upper != nullptr);
  stats.guideSeconds = secondsSince(t0);
  progress.report(0.2, "geodesics");

  t0 = std::chrono::steady_clock::now();
  std::vector<SolvedGeneratrix> solved = solveGeneratrices(gm, guide, target, bases, options, progress);
  const double meanLength = recordSearches(solved, stats);
  stats.pathSeconds = secondsSince(t0);
  std::vector<LengthBounds> exact(n);
  for (size_t i = 0; i < n; ++i) exact[i] = {solved[i].path.length, solved[i].path.length};
  requireLengthsFitWindow(exact, bases, options.window, upper != nullptr);

  t0 = std::chrono::steady_clock::now();
  const double spacing = options.pointSpacing > 0.0 ? options.pointSpacing : gm.meanEdgeLength();
  const double steps = spacing > 0.0 ? std::round(meanLength / spacing) : 2.0;
  const size_t samples = size_t(std::clamp(steps, 2.0, 100000.0)) + 1;
  std::vector<GeneratrixLine> lines = resampleLines(gm, solved, bases, samples);
  solved.clear();

  FillInContext context{gm, locator, ring, upper, std::nullopt, samples};
  if (!upper) context.closure = target.closure;
  SubProgress coverageProgress(progress, 0.85, 1.0, "coverage");
  CoverageResult coverage =
      fillCoverageGaps(std::move(lines), context, options.coverageTolerance, options.fillRounds,
                       options.maxLinesFactor * n, coverageProgress);
  stats.fillIns = coverage.fillIns;
  stats.fillRounds = coverage.rounds;
  stats.coverageError = coverage.maxError;
  stats.coverageSeconds = secondsSince(t0);

  warnAboutBaseAndCoverage(ambiguous, n, coverage, options, out.warnings);
  storeLines(coverage, target, out);
  progress.report(1.0, "generatrices");
  return out;
}

}  // namespace spira::geodesic
