#include "coverage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tbb/parallel_for.h>

namespace spira::geodesic {

namespace {

Vec3 normalAt(const GeodesicMesh& mesh, const SurfacePoint& p)
{
  return mesh.normalAt(mesh.mesh().faces[size_t(p.face)].data(), p.bary, 3);
}

// The closest point of the free edge `loop` to q, as a point of the face along that edge.
SurfacePoint closestOnLoop(const GeodesicMesh& mesh, const BoundaryLoop& loop, const Vec3& q)
{
  const auto& X = mesh.mesh().vertices;
  const auto& v = loop.vertices;
  double best = std::numeric_limits<double>::infinity(), bestT = 0.0;
  size_t bestEdge = 0;
  for (size_t i = 0; i < v.size(); ++i) {
    const Vec3& a = X[size_t(v[i])];
    const Vec3 d = X[size_t(v[(i + 1) % v.size()])] - a;
    const double dd = d.squaredNorm();
    const double t = dd > 0.0 ? std::clamp((q - a).dot(d) / dd, 0.0, 1.0) : 0.0;
    const double dist = (a + t * d - q).squaredNorm();
    if (dist < best) {
      best = dist;
      bestT = t;
      bestEdge = i;
    }
  }
  const int a = v[bestEdge], b = v[(bestEdge + 1) % v.size()];
  const int f = mesh.faceWithEdge(a, b);
  const Face& fc = mesh.mesh().faces[size_t(f)];
  Vec3 bary = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    if (fc[size_t(k)] == a) bary[k] = 1.0 - bestT;
    if (fc[size_t(k)] == b) bary[k] = bestT;
  }
  return mesh.pointOn(f, bary);
}

}  // namespace

CoverageGap coverageGap(const GeneratrixLine& a, const GeneratrixLine& b, const SurfaceLocator& locator)
{
  CoverageGap gap;
  const size_t n = std::min(a.points.size(), b.points.size());
  for (size_t k = 0; k < n; ++k) {
    const Vec3 m = 0.5 * (a.points[k] + b.points[k]);
    const double d = (locator.closest(m).position - m).norm();
    if (d > gap.error) {
      gap.error = d;
      gap.sample = k;
    }
  }
  return gap;
}

GeneratrixLine fillInBetween(const GeneratrixLine& a, const GeneratrixLine& b, const FillInContext& context)
{
  const size_t n = context.samples;
  GeneratrixLine line;
  line.fillIn = true;
  line.angle = context.base.midAngle(a.angle, b.angle);
  line.points.resize(n);
  line.normals.resize(n);
  auto put = [&](size_t k, const SurfacePoint& p) {
    line.points[k] = p.position;
    line.normals[k] = normalAt(context.mesh, p);
  };
  auto median = [&](size_t k) { return Vec3(0.5 * (a.points[k] + b.points[k])); };
  const std::optional<BasePoint> base = context.base.at(line.angle);
  put(0, base ? base->point : context.locator.closest(median(0)));
  for (size_t k = 1; k + 1 < n; ++k) put(k, context.locator.closest(median(k)));
  if (context.upper)
    put(n - 1, closestOnLoop(context.mesh, *context.upper, median(n - 1)));
  else if (context.closure)
    put(n - 1, *context.closure);
  else
    put(n - 1, context.locator.closest(median(n - 1)));
  return resampleLine(line, n);
}

CoverageResult fillCoverageGaps(std::vector<GeneratrixLine> lines, const FillInContext& context,
                                double tolerance, int maxRounds, size_t maxLines, Progress& progress)
{
  CoverageResult out;
  const double unknown = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> gap(lines.size(), unknown);  // gap[i]: between lines[i] and lines[i + 1]
  auto evaluate = [&] {
    std::vector<size_t> pending;
    for (size_t i = 0; i < gap.size(); ++i)
      if (std::isnan(gap[i])) pending.push_back(i);
    tbb::parallel_for(size_t(0), pending.size(), [&](size_t j) {
      progress.checkCancel();
      const size_t i = pending[j];
      gap[i] = coverageGap(lines[i], lines[(i + 1) % lines.size()], context.locator).error;
    });
  };
  for (;;) {
    evaluate();
    if (out.rounds >= maxRounds) break;
    std::vector<size_t> split;
    for (size_t i = 0; i < gap.size() && lines.size() + split.size() < maxLines; ++i)
      if (gap[i] > tolerance) split.push_back(i);
    if (split.empty()) break;
    std::vector<GeneratrixLine> fills(split.size());
    tbb::parallel_for(size_t(0), split.size(), [&](size_t j) {
      progress.checkCancel();
      fills[j] = fillInBetween(lines[split[j]], lines[(split[j] + 1) % lines.size()], context);
    });
    std::vector<GeneratrixLine> merged;
    std::vector<double> mergedGap;
    merged.reserve(lines.size() + fills.size());
    mergedGap.reserve(lines.size() + fills.size());
    size_t next = 0;
    for (size_t i = 0; i < lines.size(); ++i) {
      merged.push_back(std::move(lines[i]));
      if (next < split.size() && split[next] == i) {
        merged.push_back(std::move(fills[next++]));
        mergedGap.push_back(unknown);
        mergedGap.push_back(unknown);
      } else {
        mergedGap.push_back(gap[i]);
      }
    }
    lines = std::move(merged);
    gap = std::move(mergedGap);
    out.fillIns += split.size();
    ++out.rounds;
    progress.report(double(out.rounds) / double(std::max(maxRounds, 1)), "coverage");
  }
  for (size_t i = 0; i < gap.size(); ++i)
    if (gap[i] > out.maxError) {
      out.maxError = gap[i];
      out.worstPair = i;
    }
  out.converged = !(out.maxError > tolerance);
  out.lines = std::move(lines);
  return out;
}

}  // namespace spira::geodesic
