#include "spira/contour/mesh_split.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "spira/base/error.h"
#include "spira/mesh/union_find.h"

namespace spira {

namespace {

std::uint64_t edgeKey(int a, int b)
{
  const auto lo = static_cast<std::uint32_t>(std::min(a, b));
  const auto hi = static_cast<std::uint32_t>(std::max(a, b));
  return (static_cast<std::uint64_t>(lo) << 32) | hi;
}

bool selected(const std::vector<std::uint8_t>* mask, size_t f)
{
  return !mask || (*mask)[f] != 0;
}

class Cutter {
 public:
  Cutter(const TriangleMesh& mesh, const std::vector<double>& field, double level,
         const std::vector<std::uint8_t>* mask, double snap)
      : in_(mesh), field_(field), level_(level), mask_(mask)
  {
    out_.mesh.vertices = mesh.vertices;
    out_.origin.resize(mesh.vertexCount());
    for (size_t v = 0; v < mesh.vertexCount(); ++v)
      out_.origin[v] = VertexOrigin{static_cast<int>(v), static_cast<int>(v), 0.0};
    classify(snap);
  }

  LevelCut run()
  {
    for (size_t f = 0; f < in_.faceCount(); ++f) {
      const Face& fc = in_.faces[f];
      if (!selected(mask_, f)) {
        emit(fc, false, f);
        continue;
      }
      const int s[3] = {sign_[fc[0]], sign_[fc[1]], sign_[fc[2]]};
      const bool anyUp = s[0] > 0 || s[1] > 0 || s[2] > 0;
      const bool anyDown = s[0] < 0 || s[1] < 0 || s[2] < 0;
      if (!anyDown || !anyUp) {
        emit(fc, !anyDown, f);
        continue;
      }
      const int zeros = (s[0] == 0) + (s[1] == 0) + (s[2] == 0);
      if (zeros == 1) {
        // The iso-line runs from the corner on the level to the opposite edge.
        const int k = s[0] == 0 ? 0 : (s[1] == 0 ? 1 : 2);
        const int a = fc[k], b = fc[(k + 1) % 3], c = fc[(k + 2) % 3];
        const int x = crossingVertex(b, c);
        emit({a, b, x}, sign_[b] > 0, f);
        emit({a, x, c}, sign_[c] > 0, f);
      } else {
        // One corner alone on its side: a triangle there, a quad on the other side.
        const int k = (s[0] == s[1]) ? 2 : (s[0] == s[2] ? 1 : 0);
        const int a = fc[k], b = fc[(k + 1) % 3], c = fc[(k + 2) % 3];
        const int x = crossingVertex(a, b), y = crossingVertex(c, a);
        const bool aUp = sign_[a] > 0;
        emit({a, x, y}, aUp, f);
        // Split the quad x b c y along its shorter diagonal.
        const auto& P = out_.mesh.vertices;
        if ((P[x] - P[c]).squaredNorm() <= (P[b] - P[y]).squaredNorm()) {
          emit({x, b, c}, !aUp, f);
          emit({x, c, y}, !aUp, f);
        } else {
          emit({x, b, y}, !aUp, f);
          emit({b, c, y}, !aUp, f);
        }
      }
    }
    return std::move(out_);
  }

 private:
  // -1 below, 0 on the level, +1 above, for the corners of masked faces.
  void classify(double snap)
  {
    const size_t n = in_.vertexCount();
    std::vector<double> reach(n, 0.0);  // largest field step to a neighbour across the level
    sign_.assign(n, 0);
    for (size_t f = 0; f < in_.faceCount(); ++f) {
      if (!selected(mask_, f)) continue;
      for (int k = 0; k < 3; ++k) {
        const int a = in_.faces[f][k], b = in_.faces[f][(k + 1) % 3];
        const double fa = field_[a], fb = field_[b];
        if (!std::isfinite(fa) || !std::isfinite(fb))
          throw InputError("the field is not finite at vertex " + std::to_string(std::isfinite(fa) ? b : a),
                           "compute the field on this mesh before cutting it");
        if ((fa >= level_) != (fb >= level_)) {
          reach[a] = std::max(reach[a], std::abs(fb - fa));
          reach[b] = std::max(reach[b], std::abs(fb - fa));
        }
      }
    }
    for (size_t v = 0; v < n; ++v) {
      if (v >= field_.size()) break;
      const double d = field_[v] - level_;
      sign_[v] = std::abs(d) <= snap * reach[v] ? 0 : (d > 0 ? 1 : -1);
    }
  }

  // The shared new vertex where the edge between corners of opposite signs crosses the level. It is
  // computed from the ordered pair (lower id first) so that it does not depend on the face.
  int crossingVertex(int a, int b)
  {
    const std::uint64_t key = edgeKey(a, b);
    const auto it = made_.find(key);
    if (it != made_.end()) return it->second;
    const int lo = std::min(a, b), hi = std::max(a, b);
    const double t = (level_ - field_[lo]) / (field_[hi] - field_[lo]);
    const int id = static_cast<int>(out_.mesh.vertices.size());
    out_.mesh.vertices.push_back((1.0 - t) * in_.vertices[lo] + t * in_.vertices[hi]);
    out_.origin.push_back(VertexOrigin{lo, hi, t});
    made_.emplace(key, id);
    return id;
  }

  void emit(const Face& f, bool up, size_t parent)
  {
    out_.mesh.faces.push_back(f);
    out_.above.push_back(up ? 1 : 0);
    out_.parentFace.push_back(static_cast<int>(parent));
  }

  const TriangleMesh& in_;
  const std::vector<double>& field_;
  double level_;
  const std::vector<std::uint8_t>* mask_;
  std::vector<int> sign_;
  std::unordered_map<std::uint64_t, int> made_;
  LevelCut out_;
};

}  // namespace

size_t LevelCut::newVertexCount() const
{
  size_t n = 0;
  for (const auto& o : origin) n += o.v0 != o.v1;
  return n;
}

LevelCut cutAlongLevel(const TriangleMesh& mesh, const std::vector<double>& field, double level,
                       const std::vector<std::uint8_t>* faceMask, double snap)
{
  if (field.size() != mesh.vertexCount())
    throw InputError("the field has " + std::to_string(field.size()) + " values for " +
                         std::to_string(mesh.vertexCount()) + " vertices",
                     "compute the field on this mesh before cutting it");
  if (faceMask && faceMask->size() != mesh.faceCount())
    throw InternalError("cutAlongLevel: the face mask does not fit the mesh");
  if (!std::isfinite(level)) throw InternalError("cutAlongLevel: the level is not finite");
  return Cutter(mesh, field, level, faceMask, std::clamp(snap, 0.0, 0.45)).run();
}

std::vector<double> carryToCut(const LevelCut& cut, const std::vector<double>& values)
{
  std::vector<double> out(cut.origin.size());
  for (size_t v = 0; v < out.size(); ++v) {
    const VertexOrigin& o = cut.origin[v];
    out[v] = o.v0 == o.v1
                 ? values[static_cast<size_t>(o.v0)]
                 : (1.0 - o.t) * values[static_cast<size_t>(o.v0)] + o.t * values[static_cast<size_t>(o.v1)];
  }
  return out;
}

SubMesh extractFaces(const TriangleMesh& mesh, const std::vector<int>& faceIds)
{
  SubMesh out;
  std::vector<int> local(mesh.vertexCount(), -1);
  out.mesh.faces.reserve(faceIds.size());
  out.parentFace = faceIds;
  for (int f : faceIds) {
    Face g;
    for (int k = 0; k < 3; ++k) {
      const int v = mesh.faces[static_cast<size_t>(f)][k];
      if (local[static_cast<size_t>(v)] < 0) {
        local[static_cast<size_t>(v)] = static_cast<int>(out.parentVertex.size());
        out.parentVertex.push_back(v);
        out.mesh.vertices.push_back(mesh.vertices[static_cast<size_t>(v)]);
      }
      g[k] = local[static_cast<size_t>(v)];
    }
    out.mesh.faces.push_back(g);
  }
  return out;
}

int faceComponents(const TriangleMesh& mesh, const std::vector<std::uint8_t>& faceMask,
                   std::vector<int>& component)
{
  UnionFind sets(mesh.faceCount());
  std::unordered_map<std::uint64_t, int> firstFace;
  firstFace.reserve(3 * mesh.faceCount() / 2);
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!faceMask[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const auto [it, fresh] =
          firstFace.emplace(edgeKey(mesh.faces[f][k], mesh.faces[f][(k + 1) % 3]), static_cast<int>(f));
      if (!fresh) sets.unite(it->second, static_cast<int>(f));
    }
  }
  component.assign(mesh.faceCount(), -1);
  std::vector<int> labelOfRoot(mesh.faceCount(), -1);
  int count = 0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    if (!faceMask[f]) continue;
    const int root = sets.find(static_cast<int>(f));
    if (labelOfRoot[static_cast<size_t>(root)] < 0) labelOfRoot[static_cast<size_t>(root)] = count++;
    component[f] = labelOfRoot[static_cast<size_t>(root)];
  }
  return count;
}

}  // namespace spira
