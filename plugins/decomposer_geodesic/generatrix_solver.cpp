#include "generatrix_solver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "guide_trace.h"
#include "spira/base/error.h"
#include "spira/base/golden_section.h"

namespace spira::geodesic {

namespace {

constexpr int kBandRings[] = {1, 2, 4, 8, 16, 32, 64, 128, 256};
constexpr int kStarRepairs = 8;
constexpr int kGoldenSteps = 40;
constexpr long kEndReach = 2;  // upper-edge vertices either side of the guide's end kept in the band

std::string where(const Vec3& p)
{
  std::ostringstream s;
  s.precision(4);
  s << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return s.str();
}

// The point of free edge (a, b) at weight t of b, as a point of the edge's face.
SurfacePoint pointOnEdge(const GeodesicMesh& mesh, int face, int a, int b, double t)
{
  const Face& fc = mesh.mesh().faces[size_t(face)];
  Vec3 bary = Vec3::Zero();
  for (int k = 0; k < 3; ++k) {
    if (fc[size_t(k)] == a) bary[k] = 1.0 - t;
    if (fc[size_t(k)] == b) bary[k] = t;
  }
  return mesh.pointOn(face, bary);
}

}  // namespace

GeneratrixSolver::GeneratrixSolver(const GeodesicMesh& mesh, const std::vector<double>& guide,
                                   const GeodesicTarget& target)
    : mesh_(mesh), guide_(guide), target_(target)
{
}

SolvedGeneratrix GeneratrixSolver::solve(const SurfacePoint& base, Corridor& band,
                                         const Progress& progress) const
{
  TraceGoal goal;
  if (target_.open()) {
    goal.upperVertex = &target_.upperVertex;
  } else {
    goal.closureFace = target_.closure.face;
    goal.closureVertex = target_.closureVertex;
  }
  const GuideTrace trace = traceGuide(mesh_, guide_, base, goal);
  SolvedGeneratrix out;
  out.traced = trace.reached;
  // A trace stuck on the way still seeds the band, which then grows until it takes in the target.
  std::vector<int> seed = trace.faces;
  seed.push_back(base.face);
  // A closure point at a vertex can be reached in any face round it (the one the trace came by);
  // elsewhere its own face must be in the band. Adding a far face of a many-faced fan (the pole of
  // a dome) would pinch the band there and pull the whole fan in.
  if (!target_.open() && !closureAtVertex()) seed.push_back(target_.closure.face);
  // Open parts: the faces round the upper edge a few vertices either side of the trace's end,
  // where Eq. 3.7's minimum and its two neighbours along the edge are checked.
  if (target_.open()) {
    const std::vector<int>& loop = target_.upper->vertices;
    const long m = long(loop.size());
    for (int v : trace.endVertices)
      for (long d = -kEndReach; d <= kEndReach; ++d) {
        const int u = loop[size_t(((target_.upperIndex[size_t(v)] + d) % m + m) % m)];
        for (const int* c = mesh_.cornersBegin(u); c != mesh_.cornersEnd(u); ++c) seed.push_back(*c / 3);
      }
  }
  for (int rings : kBandRings) {
    progress.checkCancel();
    band.build(seed, rings);
    out.rings = rings;
    if (attempt(base, band, out)) return out;
  }
  // A band that never settled: the exact search on the whole mesh.
  progress.checkCancel();
  band.buildWholeMesh();
  out.rings = -1;
  if (attempt(base, band, out)) return out;
  throw InputError(
      "no path on the surface joins the base point at " + where(base.position) + " to the " +
          (target_.open() ? std::string("upper edge")
                          : "closure point at " + where(target_.closure.position)),
      "the part must be one connected surface from its lower edge to its top: check the mesh for "
      "gaps or separate pieces");
}

bool GeneratrixSolver::attempt(const SurfacePoint& base, Corridor& band, SolvedGeneratrix& out) const
{
  // Not worth a search tree until the band reaches the target.
  SurfacePoint closure;
  if (!target_.open() && !closureInBand(band, closure)) return false;
  if (target_.open() && std::none_of(band.vertices().begin(), band.vertices().end(),
                                     [&](int v) { return target_.upperVertex[size_t(v)] != 0; }))
    return false;
  for (int repair = 0; repair < kStarRepairs; ++repair) {
    SubmeshGeodesics geo(mesh_.mesh(), band.faces(), base);
    if (!geo.ok()) {
      band.addStars(geo.nonManifoldVertices());
      continue;
    }
    out.bandFaces = geo.faceCount();
    SurfacePoint end;
    if (target_.open()) {
      if (!chooseUpperEnd(geo, band, base, end)) return false;
    } else {
      end = closure;
    }
    ExactPath path = geo.pathTo(end);
    if (!path.reached()) return false;
    for (int v : path.throughVertices)
      if (band.isCut(v)) return false;
    out.path = std::move(path);
    out.end = end;
    return true;
  }
  return false;
}

bool GeneratrixSolver::closureAtVertex() const
{
  return target_.closure.bary.maxCoeff() >= 1.0 - 1e-12;
}

bool GeneratrixSolver::closureInBand(const Corridor& band, SurfacePoint& end) const
{
  if (band.containsFace(target_.closure.face)) {
    end = target_.closure;
    return true;
  }
  if (!closureAtVertex()) return false;
  const int v = target_.closureVertex;
  for (const int* c = mesh_.cornersBegin(v); c != mesh_.cornersEnd(v); ++c)
    if (band.containsFace(*c / 3)) {
      Vec3 bary = Vec3::Zero();
      bary[*c % 3] = 1.0;
      end = mesh_.pointOn(*c / 3, bary);
      end.position = target_.closure.position;  // the very same point, not a rounding away
      return true;
    }
  return false;
}

bool GeneratrixSolver::chooseUpperEnd(const SubmeshGeodesics& geo, const Corridor& band,
                                      const SurfacePoint& base, SurfacePoint& end) const
{
  int best = -1;
  double bestDistance = std::numeric_limits<double>::infinity();
  for (int v : band.vertices()) {
    if (!target_.upperVertex[size_t(v)]) continue;
    const double d = geo.distanceToVertex(v);
    if (d >= 0.0 && d < bestDistance) {
      bestDistance = d;
      best = v;
    }
  }
  if (best < 0) return false;
  const std::vector<int>& loop = target_.upper->vertices;
  const size_t m = loop.size();
  const size_t i = size_t(target_.upperIndex[size_t(best)]);
  const int neighbours[2] = {loop[(i + m - 1) % m], loop[(i + 1) % m]};
  for (int nb : neighbours)
    if (!band.containsVertex(nb)) return false;  // the minimum may lie beyond the band
  const int vertexFace = mesh_.faceWithEdge(best, neighbours[1]);
  end = pointOnEdge(mesh_, vertexFace, best, neighbours[1], 0.0);
  // Eq. 3.7 is a minimum over the whole edge, not its vertices: golden-section search along the
  // two edges at the nearest vertex (the distance to a point moving along a straight edge is
  // unimodal within one unfolding).
  for (int nb : neighbours) {
    const int f = mesh_.faceWithEdge(best, nb);
    if (f < 0 || !band.containsFace(f)) continue;
    auto distanceAt = [&](double t) {
      const double d = geo.distance(pointOnEdge(mesh_, f, best, nb, t));
      return d >= 0.0 ? d : std::numeric_limits<double>::infinity();
    };
    // Ties move the bracket up, as this search always has: results stay the same.
    const double t = goldenSectionMinimum(distanceAt, 0.0, 1.0, {kGoldenSteps, 0.0, GoldenTie::KeepUpper});
    const double dt = distanceAt(t);
    if (dt < bestDistance) {
      bestDistance = dt;
      end = pointOnEdge(mesh_, f, best, nb, t);
    }
  }
  // Band distances can only be too long (a path that had to go round the cut), so the minimum is
  // certain once neither neighbour can be nearer on the mesh: its straight-line distance (a lower
  // bound of any surface distance) is no shorter, or its band path passes no vertex of the cut.
  for (int nb : neighbours) {
    if ((mesh_.mesh().vertices[size_t(nb)] - base.position).norm() >= bestDistance) continue;
    const int f = mesh_.faceWithEdge(nb, best);
    if (f < 0 || !band.containsFace(f)) return false;
    const ExactPath p = geo.pathTo(pointOnEdge(mesh_, f, nb, best, 0.0));
    if (!p.reached()) return false;
    for (int through : p.throughVertices)
      if (band.isCut(through)) return false;
  }
  return true;
}

}  // namespace spira::geodesic
