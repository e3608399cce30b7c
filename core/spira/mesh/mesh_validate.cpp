#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>

#include "spira/base/error.h"
#include "spira/mesh/edge_table.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/union_find.h"
#include "spira/mesh/vertex_corners.h"
#include "spira/mesh/vertex_fans.h"
#include "spira/mesh/vertex_sort.h"

namespace spira {

namespace {

constexpr size_t kGrain = 1 << 14;
enum FaceFlag : std::uint8_t { kRepeated = 1, kZeroArea = 2, kDuplicate = 4 };

// Counts every finding and keeps the first few with a position.
class IssueList {
 public:
  explicit IssueList(MeshIssueKind kind) { issue_.kind = kind; }
  void add(int element, const Vec3& position)
  {
    if (issue_.count++ < kMaxListedIssueElements) {
      issue_.elements.push_back(element);
      issue_.positions.push_back(position);
    }
  }
  void moveInto(std::vector<MeshIssue>& out)
  {
    if (issue_.count > 0) out.push_back(std::move(issue_));
  }

 private:
  MeshIssue issue_;
};

Vec3 centroid(const TriangleMesh& m, size_t f)
{
  const Face& t = m.faces[f];
  return (m.vertices[t[0]] + m.vertices[t[1]] + m.vertices[t[2]]) / 3.0;
}

void checkIndices(const TriangleMesh& mesh)
{
  const long long nv = static_cast<long long>(mesh.vertexCount());
  const size_t bad = tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, mesh.faceCount(), kGrain), mesh.faceCount(),
      [&](const tbb::blocked_range<size_t>& r, size_t first) {
        for (size_t f = r.begin(); f != r.end() && f < first; ++f)
          for (int v : mesh.faces[f])
            if (v < 0 || v >= nv) return f;
        return first;
      },
      [](size_t a, size_t b) { return std::min(a, b); });
  if (bad == mesh.faceCount()) return;
  const Face& f = mesh.faces[bad];
  throw InputError("face " + std::to_string(bad) + " uses vertices " + std::to_string(f[0]) + ", " +
                       std::to_string(f[1]) + ", " + std::to_string(f[2]) + " but the mesh has only " +
                       std::to_string(nv) + " vertices",
                   "the mesh data is corrupt; export the part again");
}

// Flags later copies of faces with the same vertex set: faces grouped on their lowest vertex and
// sorted on (other two, face id) put copies next to each other, the first one first.
void markDuplicates(const TriangleMesh& mesh, std::vector<std::uint8_t>& flags)
{
  struct Item {
    std::uint64_t key;
    int face;
    bool operator<(const Item& o) const { return key != o.key ? key < o.key : face < o.face; }
  };
  const VertexSorted<Item> sorted =
      sortByVertex<Item>(mesh.faceCount(), mesh.vertexCount(), [&](size_t f, const auto& sink) {
        if (flags[f] & kRepeated) return;
        Face t = mesh.faces[f];
        std::sort(t.begin(), t.end());
        sink(t[0], Item{(static_cast<std::uint64_t>(t[1]) << 32) | static_cast<std::uint32_t>(t[2]),
                        static_cast<int>(f)});
      });
  tbb::parallel_for(tbb::blocked_range<size_t>(0, mesh.vertexCount(), 4096),
                    [&](const tbb::blocked_range<size_t>& r) {
                      for (size_t v = r.begin(); v != r.end(); ++v)
                        for (int i = sorted.offset[v] + 1; i < sorted.offset[v + 1]; ++i)
                          if (sorted.items[i].key == sorted.items[i - 1].key)
                            flags[sorted.items[i].face] |= kDuplicate;
                    });
}

// True when some edge with two faces is traversed the same way by both: only then is the
// (serial) search for the faces to flip needed.
bool anyInconsistentEdge(const TriangleMesh& mesh, const EdgeTable& table)
{
  return tbb::parallel_reduce(
      tbb::blocked_range<size_t>(0, table.edgeCount(), kGrain), false,
      [&](const tbb::blocked_range<size_t>& r, bool found) {
        for (size_t e = r.begin(); e != r.end() && !found; ++e)
          if (table.faceCountOf(e) == 2)
            found = halfEdgeFrom(mesh, table.halfEdges[table.edgeStart[e]]) ==
                    halfEdgeFrom(mesh, table.halfEdges[table.edgeStart[e] + 1]);
        return found;
      },
      [](bool a, bool b) { return a || b; });
}

// Per face: 1 when it is among the faces to flip (see MeshIssueKind::InconsistentOrientation).
std::vector<std::uint8_t> inconsistentFaces(const TriangleMesh& mesh, const EdgeTable& table,
                                            const std::vector<std::uint8_t>& useFace)
{
  const size_t nf = mesh.faceCount();
  std::vector<std::int8_t> state(nf, -1);  // 0: as the patch's first face, 1: flipped against it
  std::vector<std::uint8_t> out(nf, 0);
  std::vector<int> patch;
  for (size_t seed = 0; seed < nf; ++seed) {
    if (!useFace[seed] || state[seed] >= 0) continue;
    patch.assign(1, static_cast<int>(seed));
    state[seed] = 0;
    size_t flipped = 0;
    for (size_t q = 0; q < patch.size(); ++q) {
      const int f = patch[q];
      for (int k = 0; k < 3; ++k) {
        const int h = 3 * f + k;
        const int e = table.edgeOfHalfEdge[h];
        if (e < 0 || table.faceCountOf(e) != 2) continue;
        const int h0 = table.halfEdges[table.edgeStart[e]];
        const int h2 = h0 == h ? table.halfEdges[table.edgeStart[e] + 1] : h0;
        const int g = h2 / 3;
        const bool sameDirection = halfEdgeFrom(mesh, h) == halfEdgeFrom(mesh, h2);
        const std::int8_t need = static_cast<std::int8_t>(state[f] ^ (sameDirection ? 1 : 0));
        if (state[g] < 0) {
          state[g] = need;
          flipped += static_cast<size_t>(need);
          patch.push_back(g);
        } else if (state[g] != need) {
          out[std::max(f, g)] = 1;  // a non-orientable seam (Moebius): no flip set fixes it
        }
      }
    }
    const std::int8_t minority = 2 * flipped > patch.size() ? 0 : 1;
    for (int f : patch)
      if (state[f] == minority) out[f] = 1;
  }
  return out;
}

size_t countComponents(const TriangleMesh& mesh, const std::vector<std::uint8_t>& useFace)
{
  UnionFind uf(mesh.vertexCount());
  std::vector<std::uint8_t> touched(mesh.vertexCount(), 0);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!useFace[f]) continue;
    const Face& t = mesh.faces[f];
    uf.unite(t[0], t[1]);
    uf.unite(t[0], t[2]);
    touched[t[0]] = touched[t[1]] = touched[t[2]] = 1;
  }
  size_t count = 0;
  for (size_t v = 0; v < mesh.vertexCount(); ++v)
    if (touched[v] && uf.find(static_cast<int>(v)) == static_cast<int>(v)) ++count;
  return count;
}

void classify(MeshReport& r, size_t topologyFaces, size_t degenerateFaces)
{
  const size_t loops = r.boundaryLoops.size();
  r.partClass = PartClass::Unsupported;
  if (topologyFaces == 0) {
    r.classReason = "the mesh has no usable faces; import a part with a surface";
  } else if (degenerateFaces >= r.faceCount) {
    r.classReason =
        "all " + std::to_string(r.faceCount) +
        " faces are degenerate (collapsed to a point or a line): the mesh has no surface; import a "
        "part with a surface";
  } else if (loops == 1 && r.boundaryLoops.front().vertices.size() >= r.vertexCount) {
    r.classReason =
        "every vertex lies on the part's one boundary edge, so nothing of the surface is inside it "
        "(a single triangle, a flat strip or fan): a closed-top wall rises from its base edge to a "
        "top inside it; import the wall with its surface";
  } else if (r.componentCount > 1) {
    r.classReason = std::to_string(r.componentCount) +
                    " separate pieces: Spira plans one connected part at a time, so split the file "
                    "or remove the extra pieces";
  } else if (loops == 0) {
    r.classReason =
        "0 boundary loops: the mesh is watertight (a solid or a closed shell); Spira plans a thin-walled "
        "solid on its mid-surface (docs/thin-walled-solids.md), any other closed mesh needs its wall "
        "given as a surface open at the base: the wall's mid-surface (or one of its skins)";
  } else if (loops == 1) {
    r.partClass = PartClass::Closed;
    r.classReason = "1 boundary loop: a closed-top wall (a dome or cap) standing on its open base edge";
  } else if (loops == 2) {
    r.partClass = PartClass::Open;
    r.classReason = "2 boundary loops: an open wall (a tube or funnel) from its base edge to its top edge";
  } else {
    r.classReason =
        std::to_string(loops) +
        " boundary loops: the part has a hole or several branches; a branching wall (a Y-piece, a "
        "junction) is planned as one spiral per branch, a hole in a wall cannot be planned";
  }
}

}  // namespace

MeshReport validateMesh(const TriangleMesh& mesh)
{
  checkIndices(mesh);
  const size_t nv = mesh.vertexCount(), nf = mesh.faceCount();
  MeshReport r;
  r.vertexCount = nv;
  r.faceCount = nf;
  r.bounds = mesh.bounds();
  const double diag = r.bounds.diagonal();
  const double zeroArea = kDegenerateAreaRelative * diag * diag;

  IssueList nonFinite(MeshIssueKind::NonFiniteCoordinate);
  for (size_t v = 0; v < nv; ++v)
    if (!mesh.vertices[v].allFinite()) nonFinite.add(static_cast<int>(v), mesh.vertices[v]);

  std::vector<std::uint8_t> flags(nf, 0);
  // Sums use parallel_deterministic_reduce: the same chunks added in the same order whatever the
  // thread count, so the report's figures come out the same to the last bit on every run.
  r.area = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, nf, kGrain), 0.0,
      [&](const tbb::blocked_range<size_t>& range, double sum) {
        for (size_t f = range.begin(); f != range.end(); ++f) {
          const Face& t = mesh.faces[f];
          const double a = mesh.faceArea(f);
          if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
            flags[f] = kRepeated;
          else if (a <= zeroArea)  // false for NaN: non-finite faces are reported once, as such
            flags[f] = kZeroArea;
          if (std::isfinite(a)) sum += a;
        }
        return sum;
      },
      [](double a, double b) { return a + b; });
  markDuplicates(mesh, flags);

  std::vector<std::uint8_t> useFace(nf);
  size_t topologyFaces = 0;
  IssueList degenerate(MeshIssueKind::DegenerateFace), duplicate(MeshIssueKind::DuplicateFace);
  for (size_t f = 0; f < nf; ++f) {
    useFace[f] = (flags[f] & (kRepeated | kDuplicate)) == 0;
    topologyFaces += useFace[f];
    if (flags[f] & (kRepeated | kZeroArea)) degenerate.add(static_cast<int>(f), centroid(mesh, f));
    if (flags[f] & kDuplicate) duplicate.add(static_cast<int>(f), centroid(mesh, f));
  }

  const EdgeTable table = buildEdgeTable(mesh, &useFace);
  r.edgeCount = table.edgeCount();
  struct LengthSum {
    double sum = 0.0;
    size_t count = 0;
    bool nonManifold = false;
  };
  const LengthSum lengths = tbb::parallel_deterministic_reduce(
      tbb::blocked_range<size_t>(0, table.edgeCount(), kGrain), LengthSum(),
      [&](const tbb::blocked_range<size_t>& range, LengthSum acc) {
        for (size_t e = range.begin(); e != range.end(); ++e) {
          const int h = table.firstHalfEdge(e);
          const double len =
              (mesh.vertices[halfEdgeTo(mesh, h)] - mesh.vertices[halfEdgeFrom(mesh, h)]).norm();
          if (std::isfinite(len)) {
            acc.sum += len;
            ++acc.count;
          }
          acc.nonManifold |= table.faceCountOf(e) > 2;
        }
        return acc;
      },
      [](LengthSum a, const LengthSum& b) {
        return LengthSum{a.sum + b.sum, a.count + b.count, a.nonManifold || b.nonManifold};
      });
  IssueList nonManifoldEdge(MeshIssueKind::NonManifoldEdge);
  for (size_t e = 0; lengths.nonManifold && e < table.edgeCount(); ++e)
    if (table.faceCountOf(e) > 2) {
      const int h = table.firstHalfEdge(e);
      nonManifoldEdge.add(h / 3,
                          0.5 * (mesh.vertices[halfEdgeFrom(mesh, h)] + mesh.vertices[halfEdgeTo(mesh, h)]));
    }
  r.meanEdgeLength = lengths.count > 0 ? lengths.sum / static_cast<double>(lengths.count) : 0.0;

  const VertexFans fans = computeVertexFans(mesh, buildVertexCorners(mesh, &useFace));
  IssueList nonManifoldVertex(MeshIssueKind::NonManifoldVertex);
  for (size_t v = 0; v < nv; ++v)
    if (fans.fanCount[v] > 1) nonManifoldVertex.add(static_cast<int>(v), mesh.vertices[v]);

  IssueList orientation(MeshIssueKind::InconsistentOrientation);
  if (anyInconsistentEdge(mesh, table)) {
    const std::vector<std::uint8_t> flip = inconsistentFaces(mesh, table, useFace);
    for (size_t f = 0; f < nf; ++f)
      if (flip[f]) orientation.add(static_cast<int>(f), centroid(mesh, f));
  }

  nonFinite.moveInto(r.issues);
  degenerate.moveInto(r.issues);
  duplicate.moveInto(r.issues);
  nonManifoldEdge.moveInto(r.issues);
  nonManifoldVertex.moveInto(r.issues);
  orientation.moveInto(r.issues);

  r.boundaryLoops = extractBoundaryLoops(mesh, table, fans);
  r.componentCount = countComponents(mesh, useFace);
  classify(r, topologyFaces, r.issueCount(MeshIssueKind::DegenerateFace));
  return r;
}

}  // namespace spira
