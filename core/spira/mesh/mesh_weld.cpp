#include "spira/mesh/mesh_weld.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "spira/base/error.h"
#include "spira/mesh/big_vector.h"
#include "spira/mesh/radix_partition.h"
#include "spira/mesh/union_find.h"

namespace spira {

namespace {

constexpr size_t kGrain = 1 << 14;

std::uint64_t mix64(std::uint64_t h)
{
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  h *= 0xc4ceb9fe1a85ec53ULL;
  h ^= h >> 33;
  return h;
}

std::uint64_t bitsOf(double v)
{
  if (v == 0.0) v = 0.0;  // -0 and +0 are the same point
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  return b;
}

std::uint64_t rotl(std::uint64_t x, int s)
{
  return (x << s) | (x >> (64 - s));
}

std::uint64_t hashPoint(const Vec3& p)
{
  return mix64(bitsOf(p.x()) * 0x9e3779b97f4a7c15ULL + rotl(bitsOf(p.y()), 21) * 0xc2b2ae3d27d4eb4fULL +
               rotl(bitsOf(p.z()), 42) * 0x165667b19e3779f9ULL);
}

std::uint64_t hashCell(std::int64_t x, std::int64_t y, std::int64_t z)
{
  return mix64(static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ULL +
               static_cast<std::uint64_t>(y) * 0xc2b2ae3d27d4eb4fULL +
               static_cast<std::uint64_t>(z) * 0x165667b19e3779f9ULL);
}

size_t nextPow2(size_t n)
{
  size_t p = 1;
  while (p < n) p <<= 1;
  return p;
}

// Coordinates as a plain struct, so partition buffers need no construction.
struct Xyz {
  double x, y, z;
  bool operator==(const Xyz& o) const { return x == o.x && y == o.y && z == o.z; }
  bool finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(z); }
  double distance2(const Xyz& o) const
  {
    return (x - o.x) * (x - o.x) + (y - o.y) * (y - o.y) + (z - o.z) * (z - o.z);
  }
};
Xyz xyzOf(const Vec3& p)
{
  return {p.x(), p.y(), p.z()};
}

// rep[i] = smallest index with exactly the same coordinates as point i. Points (with their
// coordinates, so no random reads follow) are radix-partitioned on their hash; every bucket then
// dedups in its own small, cache-resident open-addressing table, in parallel.
// Non-finite points keep rep[i] = i.
BigVector<int> exactDuplicates(const Vec3* p, size_t n)
{
  struct Entry {
    Xyz point;
    int index;
    std::uint32_t hash;
  };
  const HashBuckets bucketOf(bucketCountFor(n, 12000));
  const auto parts = radixPartition<Entry>(n, bucketOf.count, [&](size_t i, const auto& sink) {
    const std::uint64_t h = hashPoint(p[i]);
    sink(bucketOf(h), Entry{xyzOf(p[i]), static_cast<int>(i), static_cast<std::uint32_t>(h)});
  });
  BigVector<int> rep(n);
  tbb::enumerable_thread_specific<std::vector<int>> tables;
  tbb::parallel_for(size_t{0}, parts.bucketCount(), [&](size_t q) {
    const Entry* e = parts.entries.get() + parts.start[q];
    const int m = static_cast<int>(parts.start[q + 1] - parts.start[q]);
    std::vector<int>& table = tables.local();  // positions in the bucket
    table.assign(nextPow2(2 * static_cast<size_t>(m) + 2), -1);
    const size_t mask = table.size() - 1;
    for (int k = 0; k < m; ++k) {
      int& out = rep[e[k].index];
      out = e[k].index;
      if (!e[k].point.finite()) continue;
      for (size_t s = e[k].hash & mask;; s = (s + 1) & mask) {
        const int o = table[s];
        if (o < 0) {
          table[s] = k;
          break;
        }
        if (e[o].hash == e[k].hash && e[o].point == e[k].point) {
          out = e[o].index;  // bucket keeps source order: o is the earlier point
          break;
        }
      }
    }
  });
  return rep;
}

// Pairs of distinct unique points closer than `tol`, on a uniform grid whose cells are at least
// `tol` wide, so the cells of a close pair differ by at most one along each axis. Every point is
// also listed in the upper neighbour cells whose face lies within `tol` of it (usually none: cells
// are many tolerances wide); then both points of a close pair are listed in the cell that takes the
// larger cell index of the two along every axis, and comparing the points listed in each cell finds
// all pairs. The (cell, point) entries are radix-partitioned on the cell hash, so the search
// streams through memory and runs in parallel.
std::vector<std::pair<int, int>> nearPairs(const Vec3* p, const std::vector<int>& ids, const BoundingBox& box,
                                           double tol)
{
  const size_t m = ids.size();
  const double diag = box.diagonal();
  // About 64 tolerances wide, but not much wider than the typical point spacing (or cells would
  // fill up), and never so narrow that cell coordinates overflow.
  const double spacing = diag / std::sqrt(static_cast<double>(m));
  const double cell = std::max({tol, std::min(64.0 * tol, 0.5 * spacing), diag * 1e-12});
  const double inv = 1.0 / cell;
  const double band = tol * (1.0 + 1e-6);  // a hair wider, so rounding cannot lose a borderline pair

  struct Entry {
    std::uint64_t cell;
    Xyz point;
    int id;
  };
  const HashBuckets bucketOf(bucketCountFor(m, 2048));
  const auto emit = [&](size_t k, const auto& sink) {
    const Vec3& q = p[ids[k]];
    std::int64_t c[3];
    int hi[3];
    for (int a = 0; a < 3; ++a) {
      const double t = (q[a] - box.min[a]) * inv;
      c[a] = static_cast<std::int64_t>(std::floor(t));
      hi[a] = (1.0 - (t - static_cast<double>(c[a]))) * cell <= band ? 1 : 0;
    }
    for (int dx = 0; dx <= hi[0]; ++dx)
      for (int dy = 0; dy <= hi[1]; ++dy)
        for (int dz = 0; dz <= hi[2]; ++dz) {
          const std::uint64_t h = hashCell(c[0] + dx, c[1] + dy, c[2] + dz);
          sink(bucketOf(h), Entry{h, xyzOf(q), static_cast<int>(k)});
        }
  };
  const auto parts = radixPartition<Entry>(m, bucketOf.count, emit);

  const double tol2 = tol * tol;
  struct Scratch {
    std::vector<int> heads, next;
    std::vector<std::pair<int, int>> pairs;
  };
  tbb::enumerable_thread_specific<Scratch> scratch;
  tbb::parallel_for(size_t{0}, parts.bucketCount(), [&](size_t q) {
    const Entry* e = parts.entries.get() + parts.start[q];
    const int count = static_cast<int>(parts.start[q + 1] - parts.start[q]);
    Scratch& s = scratch.local();
    s.heads.assign(nextPow2(2 * static_cast<size_t>(count) + 2), -1);
    s.next.resize(static_cast<size_t>(count));
    const size_t mask = s.heads.size() - 1;
    for (int k = 0; k < count; ++k) {
      size_t slot = static_cast<size_t>(e[k].cell) & mask;
      while (s.heads[slot] >= 0 && e[s.heads[slot]].cell != e[k].cell) slot = (slot + 1) & mask;
      // Equal 64-bit hashes of different cells would only cost extra distance checks.
      for (int j = s.heads[slot]; j >= 0; j = s.next[j])
        if (e[j].point.distance2(e[k].point) < tol2)
          s.pairs.emplace_back(std::min(e[j].id, e[k].id), std::max(e[j].id, e[k].id));
      s.next[k] = s.heads[slot];
      s.heads[slot] = k;
    }
  });
  std::vector<std::pair<int, int>> pairs;
  for (Scratch& s : scratch) pairs.insert(pairs.end(), s.pairs.begin(), s.pairs.end());
  return pairs;
}

// The size the relative tolerance applies to is the bounding-box diagonal, but at most this many
// typical (median) edges: one stray vertex far away would otherwise make the tolerance as long as
// whole triangles. Real parts span far fewer edges than this, so their tolerance is unchanged.
constexpr double kMaxSizeInEdges = 1e4;
// Edges sampled for the median: enough for a steady estimate, few enough to cost nothing.
constexpr size_t kEdgeSamples = size_t{1} << 16;

// The median length of the triangles' finite, non-zero edges (corner(t, k): corner k of triangle t),
// sampled evenly over the triangles; 0 when there is none.
template <class Corner>
double medianEdgeLength(size_t triangles, const Corner& corner)
{
  std::vector<double> lengths;
  const size_t step = std::max<size_t>(1, triangles / kEdgeSamples);
  for (size_t t = 0; t < triangles; t += step)
    for (int k = 0; k < 3; ++k) {
      const double l = (corner(t, k) - corner(t, (k + 1) % 3)).norm();
      if (std::isfinite(l) && l > 0.0) lengths.push_back(l);
    }
  if (lengths.empty()) return 0.0;
  auto mid = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), mid, lengths.end());
  return *mid;
}

struct PointWeld {
  BigVector<int> newId;    // per input point: its output vertex
  BigVector<int> firstOf;  // per output vertex: the input point that gives its position
  double tolerance = 0.0;
};

// Clusters points closer than relTol * min(bounding-box diagonal, kMaxSizeInEdges * `medianEdge`),
// transitively. Output vertices are numbered in order of their first point and sit exactly at that point.
PointWeld weldPoints(const Vec3* p, size_t n, double relTol, double medianEdge)
{
  PointWeld w;
  const BoundingBox box = finiteBounds(p, n);
  w.tolerance = box.empty() ? 0.0 : relTol * std::min(box.diagonal(), kMaxSizeInEdges * medianEdge);
  BigVector<int> rep = exactDuplicates(p, n);

  if (w.tolerance > 0.0) {
    std::vector<int> ids;  // finite unique points, in index order
    for (size_t i = 0; i < n; ++i)
      if (rep[i] == static_cast<int>(i) && p[i].allFinite()) ids.push_back(static_cast<int>(i));
    const auto pairs = nearPairs(p, ids, box, w.tolerance);
    if (!pairs.empty()) {
      UnionFind uf(ids.size());
      for (const auto& pr : pairs) uf.unite(pr.first, pr.second);
      // Root = smallest compact id = earliest point of the cluster. Unique points get their final
      // head first; the others then read it (and only it) through their exact duplicate.
      BigVector<int> head = rep;
      for (size_t k = 0; k < ids.size(); ++k) head[ids[k]] = ids[uf.find(static_cast<int>(k))];
      tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const tbb::blocked_range<size_t>& r) {
        for (size_t i = r.begin(); i != r.end(); ++i)
          if (rep[i] != static_cast<int>(i)) head[i] = head[rep[i]];
      });
      rep.swap(head);
    }
  }

  // Number the cluster heads (rep[i] == i) in index order with a chunked prefix sum.
  w.newId.resize(n);  // every entry is written below
  const size_t chunks = std::max<size_t>(1, std::min<size_t>(64, n / kGrain));
  const size_t chunkSize = (n + chunks - 1) / chunks;
  std::vector<int> base(chunks + 1, 0);
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    int k = 0;
    for (size_t i = c * chunkSize; i < std::min(n, (c + 1) * chunkSize); ++i)
      k += rep[i] == static_cast<int>(i);
    base[c + 1] = k;
  });
  for (size_t c = 0; c < chunks; ++c) base[c + 1] += base[c];
  w.firstOf.resize(static_cast<size_t>(base[chunks]));
  tbb::parallel_for(size_t{0}, chunks, [&](size_t c) {
    int k = base[c];
    for (size_t i = c * chunkSize; i < std::min(n, (c + 1) * chunkSize); ++i)
      if (rep[i] == static_cast<int>(i)) {
        w.newId[i] = k;
        w.firstOf[k++] = static_cast<int>(i);
      }
  });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n, kGrain), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t i = r.begin(); i != r.end(); ++i)
      if (rep[i] != static_cast<int>(i)) w.newId[i] = w.newId[rep[i]];
  });
  return w;
}

void checkTolerance(double relativeTolerance)
{
  if (!(relativeTolerance >= 0.0) || !std::isfinite(relativeTolerance))
    throw InputError("welding tolerance " + std::to_string(relativeTolerance) + " is not a finite value >= 0",
                     "use a small relative tolerance such as 1e-7 (a fraction of the bounding-box diagonal)");
}

}  // namespace

TriangleMesh weldVertices(const TriangleMesh& mesh, double relativeTolerance, WeldStats* stats)
{
  checkTolerance(relativeTolerance);
  const size_t nv = mesh.vertexCount();
  // Only vertices that faces use take part, so a stray point cannot bridge two real ones.
  std::vector<int> compact(nv, -1);
  for (const Face& f : mesh.faces)
    for (int v : f) {
      if (v < 0 || static_cast<size_t>(v) >= nv)
        throw InputError("a face uses vertex " + std::to_string(v) + " but the mesh has " +
                             std::to_string(nv) + " vertices",
                         "the mesh data is corrupt; export the part again");
      compact[v] = 0;
    }
  std::vector<Vec3> points;
  for (size_t v = 0; v < nv; ++v)
    if (compact[v] == 0) {
      compact[v] = static_cast<int>(points.size());
      points.push_back(mesh.vertices[v]);
    }
  const double medianEdge = medianEdgeLength(
      mesh.faceCount(), [&](size_t f, int k) -> const Vec3& { return mesh.vertices[mesh.faces[f][k]]; });
  const PointWeld w = weldPoints(points.data(), points.size(), relativeTolerance, medianEdge);

  TriangleMesh out;
  out.vertices.resize(w.firstOf.size());
  for (size_t k = 0; k < w.firstOf.size(); ++k) out.vertices[k] = points[w.firstOf[k]];
  out.faces.resize(mesh.faceCount());
  for (size_t f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) out.faces[f][k] = w.newId[compact[mesh.faces[f][k]]];
  if (stats) {
    stats->inputVertices = nv;
    stats->outputVertices = out.vertexCount();
    stats->removedUnreferenced = nv - points.size();
    stats->tolerance = w.tolerance;
  }
  return out;
}

TriangleMesh weldTriangleSoup(const std::vector<Vec3>& corners, double relativeTolerance, WeldStats* stats)
{
  checkTolerance(relativeTolerance);
  if (corners.size() % 3 != 0)
    throw InputError(
        "a triangle soup has " + std::to_string(corners.size()) + " corners, which is not a multiple of 3",
        "the mesh data is truncated or corrupt; export the part again");
  if (corners.size() >= static_cast<size_t>(std::numeric_limits<int>::max()))
    throw InputError("the mesh has too many triangles (" + std::to_string(corners.size() / 3) + ")",
                     "decimate the part below 700 million triangles");
  const size_t n = corners.size();
  const double medianEdge = medianEdgeLength(
      n / 3, [&](size_t t, int k) -> const Vec3& { return corners[3 * t + static_cast<size_t>(k)]; });
  const PointWeld w = weldPoints(corners.data(), n, relativeTolerance, medianEdge);

  TriangleMesh out;
  out.vertices.resize(w.firstOf.size());
  out.faces.resize(n / 3);
  tbb::parallel_for(tbb::blocked_range<size_t>(0, w.firstOf.size(), kGrain),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t k = r.begin(); k != r.end(); ++k) out.vertices[k] = corners[w.firstOf[k]];
                    });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, n / 3, kGrain), [&](const tbb::blocked_range<size_t>& r) {
    for (size_t f = r.begin(); f != r.end(); ++f)
      out.faces[f] = {w.newId[3 * f], w.newId[3 * f + 1], w.newId[3 * f + 2]};
  });
  if (stats) {
    stats->inputVertices = n;
    stats->outputVertices = out.vertexCount();
    stats->removedUnreferenced = 0;
    stats->tolerance = w.tolerance;
  }
  return out;
}

}  // namespace spira
