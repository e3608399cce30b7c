#include "guide_trace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace spira::geodesic {

namespace {

// Relative slack under which a barycentric coordinate counts as not decreasing along the descent,
// the same when leaving a vertex and when stepping across a face, so that the two never disagree.
constexpr double kSlack = 1e-12;

// The gradients of a face's barycentric coordinates (constant over the face): grad beta_k.
struct FaceFrame {
  std::array<Vec3, 3> gradBary;
  bool valid = false;
};

FaceFrame frameOf(const TriangleMesh& m, int f)
{
  const Face& fc = m.faces[size_t(f)];
  const Vec3 &x0 = m.vertices[size_t(fc[0])], &x1 = m.vertices[size_t(fc[1])],
             &x2 = m.vertices[size_t(fc[2])];
  const Vec3 N = (x1 - x0).cross(x2 - x0);
  const double a2 = N.norm();
  FaceFrame fr;
  if (!(a2 > 1e-300)) return fr;
  const Vec3 n = N / a2;
  fr.gradBary = {n.cross(x2 - x1) / a2, n.cross(x0 - x2) / a2, n.cross(x1 - x0) / a2};
  fr.valid = true;
  return fr;
}

Vec3 descent(const TriangleMesh& m, const FaceFrame& fr, int f, const std::vector<double>& phi)
{
  const Face& fc = m.faces[size_t(f)];
  return -(phi[size_t(fc[0])] * fr.gradBary[0] + phi[size_t(fc[1])] * fr.gradBary[1] +
           phi[size_t(fc[2])] * fr.gradBary[2]);
}

class Tracer {
 public:
  Tracer(const GeodesicMesh& gm, const std::vector<double>& phi, const TraceGoal& goal)
      : gm_(gm), m_(gm.mesh()), phi_(phi), goal_(goal)
  {
  }

  GuideTrace run(const SurfacePoint& start)
  {
    int f = start.face;
    Vec3 beta = start.bary;
    int vertex = -1;
    const size_t maxSteps = m_.faceCount() + 100;
    for (size_t step = 0; step < maxSteps; ++step) {
      if (vertex >= 0) {
        if (vertexIsGoal(vertex)) return finish({vertex});
        // The field falls all along a trace, so coming back to a vertex means it is going round
        // in circles on a flat patch: stuck.
        if (std::find(visited_.begin(), visited_.end(), vertex) != visited_.end()) return out_;
        visited_.push_back(vertex);
        addStar(vertex);
        if (!leaveVertex(vertex, f, beta)) return out_;  // a local minimum before the goal
        if (f < 0) continue;                             // moved down an edge to another vertex
        vertex = -1;
      }
      addFace(f);
      if (goal_.closureFace >= 0 && f == goal_.closureFace) return finish({});
      const FaceFrame fr = frameOf(m_, f);
      const Face& fc = m_.faces[size_t(f)];
      if (!fr.valid) {
        vertex = lowestCorner(fc);
        continue;
      }
      const Vec3 d = descent(m_, fr, f, phi_);
      const double dn = d.norm();
      if (!(dn > 0.0) || !std::isfinite(dn)) {
        vertex = lowestCorner(fc);
        continue;
      }
      // Move along d until a barycentric coordinate reaches 0.
      Vec3 db(fr.gradBary[0].dot(d), fr.gradBary[1].dot(d), fr.gradBary[2].dot(d));
      double sHit = std::numeric_limits<double>::infinity();
      int hit = -1;
      for (int k = 0; k < 3; ++k) {
        if (db[k] >= -kSlack * dn * fr.gradBary[size_t(k)].norm()) continue;
        const double s = std::max(beta[k], 0.0) / -db[k];
        if (s < sHit) {
          sHit = s;
          hit = k;
        }
      }
      if (hit < 0) {
        vertex = lowestCorner(fc);
        continue;
      }
      beta += sHit * db;
      beta[hit] = 0.0;
      beta = beta.cwiseMax(0.0);
      beta /= beta.sum();
      int zeros = 0, top = 0;
      for (int k = 0; k < 3; ++k) {
        zeros += beta[k] <= 1e-9 ? 1 : 0;
        if (beta[k] > beta[top]) top = k;
      }
      if (zeros >= 2) {
        vertex = fc[size_t(top)];
        continue;
      }
      const int a = (hit + 1) % 3, b = (hit + 2) % 3;
      const int va = fc[size_t(a)], vb = fc[size_t(b)];
      const int g = gm_.faceAcross(3 * f + a);
      if (g < 0) {
        if (goal_.upperVertex && (*goal_.upperVertex)[size_t(va)] && (*goal_.upperVertex)[size_t(vb)])
          return finish({va, vb});
        vertex = phi_[size_t(va)] <= phi_[size_t(vb)] ? va : vb;  // slide along the free edge
        continue;
      }
      // Into the face across, unless its slope leads straight back (a valley along the edge).
      const Face& gc = m_.faces[size_t(g)];
      Vec3 betaG = Vec3::Zero();
      int opposite = -1;
      for (int k = 0; k < 3; ++k) {
        if (gc[size_t(k)] == va)
          betaG[k] = beta[a];
        else if (gc[size_t(k)] == vb)
          betaG[k] = beta[b];
        else
          opposite = k;
      }
      const FaceFrame gr = frameOf(m_, g);
      if (opposite >= 0 && gr.valid && gr.gradBary[size_t(opposite)].dot(descent(m_, gr, g, phi_)) > 0.0) {
        f = g;
        beta = betaG;
        continue;
      }
      addFace(g);
      vertex = phi_[size_t(va)] <= phi_[size_t(vb)] ? va : vb;
    }
    return out_;
  }

 private:
  GuideTrace finish(std::vector<int> endVertices)
  {
    out_.endVertices = std::move(endVertices);
    out_.reached = true;
    return out_;
  }

  void addFace(int f)
  {
    if (out_.faces.empty() || out_.faces.back() != f) out_.faces.push_back(f);
  }

  void addStar(int v)
  {
    for (const int* c = gm_.cornersBegin(v); c != gm_.cornersEnd(v); ++c) addFace(*c / 3);
  }

  int lowestCorner(const Face& fc) const
  {
    int best = fc[0];
    for (int v : fc)
      if (phi_[size_t(v)] < phi_[size_t(best)]) best = v;
    return best;
  }

  bool vertexIsGoal(int v) const
  {
    if (goal_.upperVertex) return (*goal_.upperVertex)[size_t(v)] != 0;
    if (v == goal_.closureVertex) return true;
    if (goal_.closureFace >= 0)
      for (int c : m_.faces[size_t(goal_.closureFace)])
        if (c == v) return true;
    return false;
  }

  // From vertex v: into the steepest face whose descent leaves v inside it (f, beta set), or down
  // the steepest edge to a lower vertex (f = -1, v moved). False at a local minimum.
  bool leaveVertex(int& v, int& f, Vec3& beta)
  {
    double bestRate = 0.0;
    int bestFace = -1, bestCorner = -1;
    for (const int* c = gm_.cornersBegin(v); c != gm_.cornersEnd(v); ++c) {
      const int face = *c / 3, k = *c % 3;
      const FaceFrame fr = frameOf(m_, face);
      if (!fr.valid) continue;
      const Vec3 d = descent(m_, fr, face, phi_);
      const double dn = d.norm();
      if (!(dn > 0.0) || !std::isfinite(dn)) continue;
      bool inside = fr.gradBary[size_t(k)].dot(d) < -kSlack * dn * fr.gradBary[size_t(k)].norm();
      for (int j = 0; j < 3 && inside; ++j)
        if (j != k && fr.gradBary[size_t(j)].dot(d) < -kSlack * dn * fr.gradBary[size_t(j)].norm())
          inside = false;
      if (inside && dn > bestRate) {
        bestRate = dn;
        bestFace = face;
        bestCorner = k;
      }
    }
    if (bestFace >= 0) {
      f = bestFace;
      beta = Vec3::Zero();
      beta[bestCorner] = 1.0;
      return true;
    }
    const auto& adj = gm_.adjacency();
    const Vec3& x = m_.vertices[size_t(v)];
    double bestSlope = 0.0;
    int next = -1;
    for (int i = adj.neighborStart[size_t(v)]; i < adj.neighborStart[size_t(v) + 1]; ++i) {
      const int u = adj.neighbors[size_t(i)];
      const double len = (m_.vertices[size_t(u)] - x).norm();
      if (!(len > 0.0)) continue;
      const double slope = (phi_[size_t(v)] - phi_[size_t(u)]) / len;
      if (slope > bestSlope) {
        bestSlope = slope;
        next = u;
      }
    }
    if (next < 0) return false;
    v = next;
    f = -1;
    return true;
  }

  const GeodesicMesh& gm_;
  const TriangleMesh& m_;
  const std::vector<double>& phi_;
  const TraceGoal& goal_;
  GuideTrace out_;
  std::vector<int> visited_;  // vertices the trace passed through (few: it mostly crosses faces)
};

}  // namespace

GuideTrace traceGuide(const GeodesicMesh& mesh, const std::vector<double>& phi, const SurfacePoint& start,
                      const TraceGoal& goal)
{
  return Tracer(mesh, phi, goal).run(start);
}

}  // namespace spira::geodesic
