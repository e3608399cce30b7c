#include "spira/thermal/thermal_mesh.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "spira/base/error.h"
#include "spira/path/dwell.h"

namespace spira {
namespace {

// Builds the mesh in creation order; buildThermalMesh renumbers it by birth at the end.
class MeshBuilder {
 public:
  MeshBuilder(const Trajectory& t, const ThermalMeshSettings& s) : traj_(t), s_(s) {}

  ThermalMesh build()
  {
    mesh_.thickness = s_.thickness;
    mesh_.pointHeatIndex.assign(traj_.size(), -1);
    mesh_.pointBelowNode.assign(traj_.size(), -1);
    size_t begin = 0;
    while (begin < traj_.size()) {
      size_t end = begin + 1;
      while (end < traj_.size() && traj_.points[end].path == traj_.points[begin].path) ++end;
      buildBlock(begin, end);
      begin = end;
    }
    return std::move(mesh_);
  }

 private:
  int addNode(const Vec3& p, int owner)
  {
    mesh_.nodes.push_back(p);
    owner_.push_back(owner);
    return int(mesh_.nodes.size()) - 1;
  }

  double speedOf(size_t i) const
  {
    const double v = traj_.points[i].travelSpeed;
    if (!(v > 0.0) || !std::isfinite(v))
      throw InputError(
          "trajectory point " + std::to_string(i) + " has no travel speed (" + std::to_string(v) + " mm/s)",
          "the thermal model needs the process channels: plan with the process stage");
    return v;
  }

  // The heat path of points [begin, end): trajectory points and k - 1 points between each pair.
  // Returns the block's heat nodes (local heat index j * k + s).
  std::vector<int> heatLine(size_t begin, size_t end)
  {
    const int k = s_.subSegments;
    std::vector<int> line;
    for (size_t i = begin; i < end; ++i) {
      const TrajectoryPoint& p = traj_.points[i];
      if (!mesh_.heatTime.empty()) {
        const Vec3 from = traj_.points[i - 1].position;
        const double len = (p.position - from).norm();
        // Inside a path each segment is run at its first point's speed, as the process model times
        // the build (report.json build_time_s); the move from one path to the next is a travel at the
        // next point's speed.
        const double v = i == begin ? speedOf(i) : speedOf(i - 1);
        const bool arc = i != begin && p.arcOn && traj_.points[i - 1].arcOn;
        // A dwell: the torch waits at the previous point, arc off, before this segment.
        if (const double wait = i == begin ? 0.0 : dwellAt(traj_, i - 1); wait > 0.0) {
          mesh_.heatArcOn.push_back(0);
          mesh_.heatWireFeed.push_back(0.0);
          mesh_.heatTime.push_back(mesh_.heatTime.back() + wait);
          mesh_.heatNode.push_back(mesh_.heatNode.back());
        }
        const double t0 = mesh_.heatTime.back();
        const int sub = i == begin ? 1 : k;
        for (int q = 1; q <= sub; ++q) {
          const double f = double(q) / sub;
          const Vec3 pos = from + f * (p.position - from);
          mesh_.heatArcOn.push_back(char(arc));
          mesh_.heatWireFeed.push_back(traj_.points[i - 1].wireFeed);
          mesh_.heatTime.push_back(t0 + f * len / v);
          const bool same = len < 1e-9 && i != begin;
          // A repeated point shares its node: a zero-length segment would give zero-area elements.
          const int node = same ? line.back() : addNode(pos, int(mesh_.heatTime.size()) - 1);
          mesh_.heatNode.push_back(node);
          if (i != begin) line.push_back(node);
        }
        if (i == begin) line.push_back(mesh_.heatNode.back());
      } else {
        speedOf(i);
        mesh_.heatTime.push_back(0.0);
        const int node = addNode(p.position, 0);
        mesh_.heatNode.push_back(node);
        line.push_back(node);
      }
      mesh_.pointHeatIndex[i] = int(mesh_.heatNode.size()) - 1;
    }
    return line;
  }

  void addTriangle(int a, int b, int c, int substrateA = -1, int substrateB = -1)
  {
    if (a == b || b == c || a == c) return;
    const Vec3& p = mesh_.nodes[size_t(a)];
    const double area2 = (mesh_.nodes[size_t(b)] - p).cross(mesh_.nodes[size_t(c)] - p).norm();
    if (area2 < 1e-12) return;
    mesh_.triangles.push_back({a, b, c});
    mesh_.substrateEdge.push_back({substrateA, substrateB});
  }

  // Joins a row of top nodes (at coordinates u along `bottom`, whose node b sits at b) to the
  // bottom row through f - 1 intermediate rows: quads split in two where the rows match, a zipper
  // (each step advancing the row whose next node comes first) where they do not.
  void strip(const std::vector<int>& top, std::vector<double> u, const std::vector<int>& bottom,
             bool substrate)
  {
    const int nb = int(bottom.size());
    for (double& x : u) x = std::clamp(x, 0.0, double(nb - 1));
    for (size_t j = 1; j < u.size(); ++j) u[j] = std::max(u[j], u[j - 1]);
    const auto bottomAt = [&](double x) {
      const int b0 = std::min(int(std::floor(x)), nb - 1);
      const int b1 = std::min(b0 + 1, nb - 1);
      const double w = x - b0;
      return Vec3((1.0 - w) * mesh_.nodes[size_t(bottom[size_t(b0)])] +
                  w * mesh_.nodes[size_t(bottom[size_t(b1)])]);
    };
    std::vector<int> upper = top;
    std::vector<int> firstColumn{top.front()}, lastColumn{top.back()};
    const int f = top.size() > 1 ? s_.divisions : 1;
    for (int row = f - 1; row >= 1; --row) {
      std::vector<int> lower;
      for (size_t j = 0; j < top.size(); ++j) {
        const Vec3& t = mesh_.nodes[size_t(top[j])];
        lower.push_back(
            addNode(bottomAt(u[j]) + double(row) / f * (t - bottomAt(u[j])), owner_[size_t(top[j])]));
      }
      for (size_t j = 0; j + 1 < top.size(); ++j) {
        addTriangle(upper[j], upper[j + 1], lower[j + 1]);
        addTriangle(upper[j], lower[j + 1], lower[j]);
      }
      upper = std::move(lower);
      firstColumn.push_back(upper.front());
      lastColumn.push_back(upper.back());
    }
    // Where the bottom row reaches past the top row's ends, the intermediate rows' end columns close
    // on the bottom's end nodes (the zipper below only joins the lowest row).
    for (size_t c = 0; c + 1 < firstColumn.size(); ++c) {
      if (u.front() > 1e-9) addTriangle(firstColumn[c], firstColumn[c + 1], bottom.front());
      if (u.back() < nb - 1 - 1e-9) addTriangle(lastColumn[c], lastColumn[c + 1], bottom.back());
    }
    const int m = int(upper.size()) - 1;
    int j = 0, b = 0;
    while (j < m || b < nb - 1) {
      const bool advanceTop = b == nb - 1 || (j < m && u[size_t(j + 1)] < b + 1 - 1e-9);
      if (advanceTop) {
        addTriangle(upper[size_t(j)], upper[size_t(j + 1)], bottom[size_t(b)]);
        ++j;
      } else {
        const int b0 = bottom[size_t(b)], b1 = bottom[size_t(b + 1)];
        if (substrate)
          addTriangle(upper[size_t(j)], b0, b1, b0, b1);
        else
          addTriangle(upper[size_t(j)], b0, b1);
        ++b;
      }
    }
  }

  int nearestEarlierNode(const Vec3& p, int count) const
  {
    int best = 0;
    double d = std::numeric_limits<double>::infinity();
    for (int i = 0; i < count; ++i) {
      const double e = (mesh_.nodes[size_t(i)] - p).squaredNorm();
      if (e < d) d = e, best = i;
    }
    return best;
  }

  void buildBlock(size_t begin, size_t end)
  {
    const int k = s_.subSegments;
    const int earlierNodes = int(mesh_.nodes.size());
    const std::vector<int> line = heatLine(begin, end);
    const int m = int(end - begin);
    // Revolutions: runs of points with the same revolution index.
    std::vector<int> revStart{0};
    for (int j = 1; j < m; ++j)
      if (traj_.points[begin + size_t(j)].revolution != traj_.points[begin + size_t(j) - 1].revolution)
        revStart.push_back(j);
    const int nRev = int(revStart.size());
    const auto topEnd = [&](int r) { return r + 1 < nRev ? revStart[size_t(r + 1)] * k : (m - 1) * k; };

    // The first revolution rests on the substrate plane, or on the earlier paths for a branch.
    const int end0 = topEnd(0);
    double lowest = std::numeric_limits<double>::infinity();
    for (int h = 0; h <= end0; ++h) lowest = std::min(lowest, mesh_.nodes[size_t(line[size_t(h)])].z());
    const bool onSubstrate = earlierNodes == 0 || lowest - s_.substrateZ <= s_.substrateContact;
    std::vector<int> top(line.begin(), line.begin() + end0 + 1), bottom;
    std::vector<double> u;
    for (int h = 0; h <= end0; ++h) {
      const Vec3& p = mesh_.nodes[size_t(line[size_t(h)])];
      if (onSubstrate) {
        bottom.push_back(addNode(Vec3(p.x(), p.y(), s_.substrateZ), -1));
        mesh_.substrateNodes.push_back(bottom.back());
      } else {
        bottom.push_back(nearestEarlierNode(p, earlierNodes));
      }
      u.push_back(h);
    }
    for (int j = 0; j * k <= end0 && j < m; ++j)
      mesh_.pointBelowNode[begin + size_t(j)] = bottom[size_t(j * k)];
    strip(top, u, bottom, onSubstrate);

    for (int r = 1; r < nRev; ++r) {
      const int b0 = revStart[size_t(r - 1)] * k, b1 = revStart[size_t(r)] * k, t1 = topEnd(r);
      bottom.assign(line.begin() + b0, line.begin() + b1 + 1);
      top.assign(line.begin() + b1, line.begin() + t1 + 1);
      // The point below: on revolutions of equal point count, the same generatrix on the previous one
      // (the planner's generatrices are shared by all revolutions); otherwise the point at the same
      // fraction of the revolution's length, so that counts that differ cannot cross the zipper.
      const int jEnd = r + 1 < nRev ? revStart[size_t(r + 1)] : m - 1;
      const int count = (r + 1 < nRev ? revStart[size_t(r + 1)] : m) - revStart[size_t(r)];
      const bool sameCount = count == revStart[size_t(r)] - revStart[size_t(r - 1)];
      std::vector<std::pair<int, int>> previous;
      for (int j = revStart[size_t(r - 1)]; j < revStart[size_t(r)]; ++j)
        previous.emplace_back(traj_.points[begin + size_t(j)].generatrix, j);
      std::sort(previous.begin(), previous.end());
      const auto byGeneratrix = [&](int j) {
        const int g = traj_.points[begin + size_t(j)].generatrix;
        auto it = std::lower_bound(previous.begin(), previous.end(), std::make_pair(g, -1));
        if (it == previous.end() || (it != previous.begin() && g - std::prev(it)->first < it->first - g))
          --it;
        return double(it->second * k - b0);
      };
      const auto lengthsOf = [&](int from, int to) {  // cumulative lengths along points [from, to]
        std::vector<double> len{0.0};
        for (int j = from + 1; j <= to; ++j)
          len.push_back(len.back() + (traj_.points[begin + size_t(j)].position -
                                      traj_.points[begin + size_t(j) - 1].position)
                                         .norm());
        return len;
      };
      const std::vector<double> topLength = lengthsOf(revStart[size_t(r)], jEnd);
      const std::vector<double> bottomLength = lengthsOf(revStart[size_t(r - 1)], revStart[size_t(r)]);
      const auto byLength = [&](int j) {
        const double f =
            topLength.back() > 0.0 ? topLength[size_t(j - revStart[size_t(r)])] / topLength.back() : 0.0;
        const double target = f * bottomLength.back();
        const size_t i =
            size_t(std::upper_bound(bottomLength.begin(), bottomLength.end(), target) - bottomLength.begin());
        if (i >= bottomLength.size()) return double(b1 - b0);
        const double w =
            (target - bottomLength[i - 1]) / std::max(1e-300, bottomLength[i] - bottomLength[i - 1]);
        return (double(i - 1) + w) * k;
      };
      std::vector<double> pointU;
      for (int j = revStart[size_t(r)]; j <= jEnd; ++j) {
        // The point that opens the next revolution sits over the end of this strip's bottom.
        if (r + 1 < nRev && j == jEnd)
          pointU.push_back(double(b1 - b0));
        else
          pointU.push_back(sameCount ? byGeneratrix(j) : byLength(j));
      }
      for (size_t q = 1; q < pointU.size(); ++q) pointU[q] = std::max(pointU[q], pointU[q - 1]);
      u.clear();
      for (size_t q = 0; q < pointU.size(); ++q) {
        u.push_back(pointU[q]);
        if (q + 1 < pointU.size())
          for (int s = 1; s < k; ++s) u.push_back(pointU[q] + double(s) / k * (pointU[q + 1] - pointU[q]));
      }
      for (int j = revStart[size_t(r)]; j < jEnd || (j == jEnd && r + 1 == nRev); ++j) {
        const int b =
            int(std::lround(std::clamp(pointU[size_t(j - revStart[size_t(r)])], 0.0, double(b1 - b0))));
        mesh_.pointBelowNode[begin + size_t(j)] = bottom[size_t(b)];
      }
      strip(top, u, bottom, false);
    }
  }

 public:
  std::vector<int> owner_;  // heat-path index that creates each node, -1 for substrate nodes

 private:
  const Trajectory& traj_;
  const ThermalMeshSettings& s_;
  ThermalMesh mesh_;
};

void validate(const Trajectory& t, const ThermalMeshSettings& s)
{
  if (t.empty()) throw InputError("the trajectory is empty", "plan a part first");
  if (s.subSegments < 1 || s.divisions < 1)
    throw InputError("sub-segments and divisions must be at least 1",
                     "use k = 1 and f = 1 for the coarsest mesh");
  if (!(s.thickness > 0.0))
    throw InputError("the shell thickness must be positive", "use the bead width, about 5 mm");
}

}  // namespace

int ThermalMesh::nearestNode(const Vec3& p) const
{
  int best = -1;
  double d = std::numeric_limits<double>::infinity();
  for (size_t i = 0; i < nodes.size(); ++i) {
    const double e = (nodes[i] - p).squaredNorm();
    if (e < d) d = e, best = int(i);
  }
  return best;
}

ThermalMesh buildThermalMesh(const Trajectory& trajectory, const ThermalMeshSettings& settings)
{
  validate(trajectory, settings);
  MeshBuilder builder(trajectory, settings);
  ThermalMesh mesh = builder.build();
  const std::vector<int>& owner = builder.owner_;
  const int nHeat = int(mesh.heatTime.size());
  // Block starts: a heat index whose predecessor segment is a move between paths.
  std::vector<char> blockStart(size_t(nHeat), 0);
  blockStart[0] = 1;
  for (size_t i = 0; i < trajectory.size(); ++i)
    if (i > 0 && trajectory.points[i].path != trajectory.points[i - 1].path)
      blockStart[size_t(mesh.pointHeatIndex[i])] = 1;
  // An element is born when the torch starts the sub-segment that reaches its newest node.
  mesh.elementBirth.resize(mesh.triangles.size());
  for (size_t e = 0; e < mesh.triangles.size(); ++e) {
    int h = 0;
    for (int n : mesh.triangles[e]) h = std::max(h, owner[size_t(n)]);
    mesh.elementBirth[e] = mesh.heatTime[size_t(blockStart[size_t(h)] ? h : h - 1)];
  }
  // Renumber the nodes by birth (the first element that holds them), ties in creation order.
  const size_t n = mesh.nodes.size();
  std::vector<double> birth(n, std::numeric_limits<double>::infinity());
  for (size_t e = 0; e < mesh.triangles.size(); ++e)
    for (int v : mesh.triangles[e]) birth[size_t(v)] = std::min(birth[size_t(v)], mesh.elementBirth[e]);
  for (size_t v = 0; v < n; ++v)
    if (!std::isfinite(birth[v])) birth[v] = owner[v] >= 0 ? mesh.heatTime[size_t(owner[v])] : 0.0;
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return birth[size_t(a)] < birth[size_t(b)]; });
  std::vector<int> newIndex(n);
  for (size_t i = 0; i < n; ++i) newIndex[size_t(order[i])] = int(i);
  std::vector<Vec3> nodes(n);
  for (size_t i = 0; i < n; ++i) nodes[i] = mesh.nodes[size_t(order[i])];
  mesh.nodes = std::move(nodes);
  const auto remap = [&](int& v) {
    if (v >= 0) v = newIndex[size_t(v)];
  };
  for (auto& t : mesh.triangles)
    for (int& v : t) remap(v);
  for (auto& e : mesh.substrateEdge)
    for (int& v : e) remap(v);
  for (int& v : mesh.substrateNodes) remap(v);
  for (int& v : mesh.heatNode) remap(v);
  for (int& v : mesh.pointBelowNode) remap(v);
  return mesh;
}

NodeAdjacency nodeAdjacency(const ThermalMesh& mesh)
{
  const size_t n = mesh.nodeCount();
  std::vector<std::vector<int>> adjacent(n);
  for (const auto& t : mesh.triangles)
    for (int a = 0; a < 3; ++a) {
      adjacent[size_t(t[size_t(a)])].push_back(t[size_t((a + 1) % 3)]);
      adjacent[size_t(t[size_t(a)])].push_back(t[size_t((a + 2) % 3)]);
    }
  NodeAdjacency out;
  out.start.assign(n + 1, 0);
  for (size_t v = 0; v < n; ++v) {
    auto& a = adjacent[v];
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    out.start[v + 1] = out.start[v] + int(a.size());
    out.neighbours.insert(out.neighbours.end(), a.begin(), a.end());
  }
  return out;
}

}  // namespace spira
