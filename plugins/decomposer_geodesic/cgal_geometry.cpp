// The only translation unit of the geodesic decomposer that includes CGAL (slow to compile, and
// never to be mixed with OpenCASCADE headers): the exact shortest-path tree on a sub-mesh and the
// closest-point tree over the whole mesh.
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_shortest_path.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "path_straightening.h"
#include "spira/base/error.h"
#include "submesh_geodesics.h"
#include "surface_locator.h"

namespace spira::geodesic {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point3 = Kernel::Point_3;
using CgalMesh = CGAL::Surface_mesh<Point3>;
using VertexIndex = CgalMesh::Vertex_index;
using FaceIndex = CgalMesh::Face_index;
using HalfedgeIndex = CgalMesh::Halfedge_index;

constexpr double kPi = 3.14159265358979323846;
constexpr double kSnap = 1e-7;  // barycentric weight below which a point is on the edge or vertex

// CGAL's traits with one change: a vertex counts as a saddle (a pseudo-source of the search) only
// when its angle sum exceeds 2 pi by more than 1e-6 relative. CGAL's own test also counts the
// flat vertices (sum = 2 pi up to rounding), where a geodesic goes straight on; on developable
// parts, where every vertex is flat, that multiplies the cone-tree nodes.
struct FlatTolerantTraits : CGAL::Surface_mesh_shortest_path_traits<Kernel, CgalMesh> {
  struct IsSaddleVertex {
    template <class PointMap>
    bool operator()(VertexIndex v, const CgalMesh& g, const PointMap& points) const
    {
      double sum = 0.0;
      for (HalfedgeIndex h : CGAL::halfedges_around_target(v, g)) {
        if (CGAL::is_border(h, g)) continue;
        const Point3& p = get(points, g.source(h));
        const Point3& q = get(points, g.target(h));
        const Point3& r = get(points, g.target(g.next(h)));
        const Kernel::Vector_3 a = p - q, b = r - q;
        sum += std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
      }
      return sum > 2.0 * kPi * (1.0 + 1e-6);
    }
  };
  IsSaddleVertex is_saddle_vertex_object() const { return {}; }
};

using ShortestPath = CGAL::Surface_mesh_shortest_path<FlatTolerantTraits>;
using Location = ShortestPath::Face_location;

Point3 toCgal(const Vec3& p)
{
  return Point3(p.x(), p.y(), p.z());
}

Vec3 toVec(const Point3& p)
{
  return Vec3(p.x(), p.y(), p.z());
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// SubmeshGeodesics

struct SubmeshGeodesics::Impl {
  const TriangleMesh& full;
  std::vector<int> vertexGlobal;  // sorted: local vertex i is mesh vertex vertexGlobal[i]
  std::vector<int> faceGlobal;    // sorted: CGAL face i is mesh face faceGlobal[i]
  std::vector<int> nonManifold;
  CgalMesh sm;
  std::unique_ptr<ShortestPath> tree;

  explicit Impl(const TriangleMesh& m) : full(m) {}

  int localVertex(int global) const
  {
    auto it = std::lower_bound(vertexGlobal.begin(), vertexGlobal.end(), global);
    return it != vertexGlobal.end() && *it == global ? int(it - vertexGlobal.begin()) : -1;
  }
  int localFace(int global) const
  {
    auto it = std::lower_bound(faceGlobal.begin(), faceGlobal.end(), global);
    return it != faceGlobal.end() && *it == global ? int(it - faceGlobal.begin()) : -1;
  }
  int global(VertexIndex v) const { return vertexGlobal[size_t(v)]; }

  // CGAL orders a face's barycentric coordinates from halfedge(f): source, target, next target.
  std::array<VertexIndex, 3> cornersOf(FaceIndex f) const
  {
    const HalfedgeIndex h = sm.halfedge(f);
    return {sm.source(h), sm.target(h), sm.target(sm.next(h))};
  }

  bool locate(const SurfacePoint& p, Location& out) const
  {
    const int lf = p.face >= 0 ? localFace(p.face) : -1;
    if (lf < 0) return false;
    const FaceIndex f(static_cast<CgalMesh::size_type>(lf));
    const Face& fc = full.faces[size_t(p.face)];
    const auto corners = cornersOf(f);
    std::array<double, 3> coords{0.0, 0.0, 0.0};
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 3; ++k)
        if (fc[size_t(k)] == global(corners[size_t(i)])) coords[size_t(i)] = p.bary[k];
    // A point a rounding error away from a vertex or an edge is put on it: paths from a point
    // 1e-16 beside a vertex run along the mesh edges through it, where CGAL's unfolded
    // intersections degenerate.
    double sum = 0.0;
    for (double& c : coords) {
      c = c < kSnap ? 0.0 : c;
      sum += c;
    }
    for (double& c : coords) c /= sum;
    out = Location(f, ShortestPath::Barycentric_coordinates{coords[0], coords[1], coords[2]});
    return true;
  }

  // Collects the path from the query point back to the source as PathPoints (mesh vertex ids).
  struct PathCollector {
    const Impl* impl;
    ExactPath* path;

    void push(const PathPoint& p)
    {
      if (!path->points.empty() && (path->points.back().position - p.position).squaredNorm() < 1e-18) return;
      path->points.push_back(p);
    }
    void operator()(HalfedgeIndex h, double t)
    {
      const CgalMesh& sm = impl->sm;
      PathPoint p;
      p.vertices = {impl->global(sm.source(h)), impl->global(sm.target(h)), -1};
      // Where the path runs along a mesh edge the unfolded intersection is ill-conditioned and t
      // may leave [0, 1]; the crossing is then the edge's end.
      t = std::clamp(t, 0.0, 1.0);
      p.weights = Vec3(1.0 - t, t, 0.0);
      p.position = (1.0 - t) * toVec(sm.point(sm.source(h))) + t * toVec(sm.point(sm.target(h)));
      push(p);
    }
    void operator()(VertexIndex v)
    {
      PathPoint p;
      p.vertices = {impl->global(v), -1, -1};
      p.weights = Vec3(1.0, 0.0, 0.0);
      p.position = toVec(impl->sm.point(v));
      path->throughVertices.push_back(p.vertices[0]);
      push(p);
    }
    void operator()(FaceIndex f, const ShortestPath::Barycentric_coordinates& b)
    {
      const auto corners = impl->cornersOf(f);
      PathPoint p;
      for (size_t i = 0; i < 3; ++i) {
        p.vertices[i] = impl->global(corners[i]);
        p.weights[int(i)] = b[i];
        p.position += b[i] * toVec(impl->sm.point(corners[i]));
      }
      push(p);
    }
  };
};

SubmeshGeodesics::SubmeshGeodesics(const TriangleMesh& mesh, const std::vector<int>& faces,
                                   const SurfacePoint& source)
    : impl_(std::make_unique<Impl>(mesh))
{
  Impl& m = *impl_;
  // Faces without area (a repeated corner, or three corners on a line) have no unfolding: left
  // out, they are holes the paths go round.
  m.faceGlobal.reserve(faces.size());
  for (int f : faces) {
    const Face& fc = mesh.faces[size_t(f)];
    if (fc[0] != fc[1] && fc[1] != fc[2] && fc[0] != fc[2] &&
        mesh.faceNormalScaled(size_t(f)).squaredNorm() > 0.0)
      m.faceGlobal.push_back(f);
  }
  std::sort(m.faceGlobal.begin(), m.faceGlobal.end());
  m.faceGlobal.erase(std::unique(m.faceGlobal.begin(), m.faceGlobal.end()), m.faceGlobal.end());
  m.vertexGlobal.reserve(m.faceGlobal.size() * 3);
  for (int f : m.faceGlobal)
    for (int v : mesh.faces[size_t(f)]) m.vertexGlobal.push_back(v);
  std::sort(m.vertexGlobal.begin(), m.vertexGlobal.end());
  m.vertexGlobal.erase(std::unique(m.vertexGlobal.begin(), m.vertexGlobal.end()), m.vertexGlobal.end());

  m.sm.reserve(CgalMesh::size_type(m.vertexGlobal.size()), CgalMesh::size_type(3 * m.faceGlobal.size()),
               CgalMesh::size_type(m.faceGlobal.size()));
  for (int v : m.vertexGlobal) m.sm.add_vertex(toCgal(mesh.vertices[size_t(v)]));
  for (int f : m.faceGlobal) {
    const Face& fc = mesh.faces[size_t(f)];
    const VertexIndex a(CgalMesh::size_type(m.localVertex(fc[0]))),
        b(CgalMesh::size_type(m.localVertex(fc[1]))), c(CgalMesh::size_type(m.localVertex(fc[2])));
    if (m.sm.add_face(a, b, c) == CgalMesh::null_face())
      m.nonManifold.insert(m.nonManifold.end(), fc.begin(), fc.end());
  }
  if (!m.nonManifold.empty()) {
    std::sort(m.nonManifold.begin(), m.nonManifold.end());
    m.nonManifold.erase(std::unique(m.nonManifold.begin(), m.nonManifold.end()), m.nonManifold.end());
    return;
  }
  Location sourceLocation;
  if (!m.locate(source, sourceLocation))
    throw InputError("a generatrix starts on face " + std::to_string(source.face) + ", which has no area",
                     "repair the mesh: remove its degenerate faces");
  // CGAL 5.5 mirrors a source lying exactly on an edge (expand_edge_root passes the weight of the
  // edge's first vertex where face_location expects the second's), and every base point lies on
  // the lower edge: such sources are moved 1e-9 of the way into their face, where they are exact.
  auto& w = sourceLocation.second;
  const int zeros = (w[0] == 0.0) + (w[1] == 0.0) + (w[2] == 0.0);
  if (zeros == 1) {
    for (double& c : w) c = c == 0.0 ? 1e-9 : c * (1.0 - 1e-9);
  }
  m.tree = std::make_unique<ShortestPath>(m.sm);
  m.tree->add_source_point(sourceLocation);
  m.tree->build_sequence_tree();
}

SubmeshGeodesics::~SubmeshGeodesics() = default;

bool SubmeshGeodesics::ok() const
{
  return impl_->tree != nullptr;
}

const std::vector<int>& SubmeshGeodesics::nonManifoldVertices() const
{
  return impl_->nonManifold;
}

size_t SubmeshGeodesics::faceCount() const
{
  return impl_->faceGlobal.size();
}

double SubmeshGeodesics::distance(const SurfacePoint& p) const
{
  Location loc;
  if (!impl_->tree || !impl_->locate(p, loc)) return -1.0;
  return impl_->tree->shortest_distance_to_source_points(loc.first, loc.second).first;
}

double SubmeshGeodesics::distanceToVertex(int v) const
{
  const int lv = impl_->localVertex(v);
  if (!impl_->tree || lv < 0) return -1.0;
  return impl_->tree->shortest_distance_to_source_points(VertexIndex(CgalMesh::size_type(lv))).first;
}

ExactPath SubmeshGeodesics::pathTo(const SurfacePoint& p) const
{
  ExactPath path;
  Location loc;
  if (!impl_->tree || !impl_->locate(p, loc)) return path;
  Impl::PathCollector collector{impl_.get(), &path};
  path.length = impl_->tree->shortest_path_sequence_to_source_points(loc.first, loc.second, collector).first;
  if (!path.reached()) {
    path.points.clear();
    path.throughVertices.clear();
    return path;
  }
  std::reverse(path.points.begin(), path.points.end());
  const Impl& m = *impl_;
  StripMesh strip;
  strip.position = [&m](int v) { return m.full.vertices[static_cast<size_t>(v)]; };
  strip.opposite = [&m](int a, int b) {
    std::array<int, 2> out{-1, -1};
    const int la = m.localVertex(a), lb = m.localVertex(b);
    if (la < 0 || lb < 0) return out;
    const HalfedgeIndex h =
        m.sm.halfedge(VertexIndex(CgalMesh::size_type(la)), VertexIndex(CgalMesh::size_type(lb)));
    if (h == CgalMesh::null_halfedge()) return out;
    const HalfedgeIndex sides[2] = {h, m.sm.opposite(h)};
    for (int k = 0; k < 2; ++k)
      if (!m.sm.is_border(sides[k])) out[size_t(k)] = m.global(m.sm.target(m.sm.next(sides[k])));
    return out;
  };
  straightenPath(path, path.length, strip);
  return path;
}

// ---------------------------------------------------------------------------------------------
// SurfaceLocator

namespace {
using Triangles = std::vector<Kernel::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, Triangles::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

// Barycentric weights of q (a point of the triangle's plane) clamped into the triangle.
Vec3 barycentricOf(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c)
{
  const Vec3 e0 = b - a, e1 = c - a, d = q - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1);
  const double d20 = d.dot(e0), d21 = d.dot(e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(std::abs(den) > 0.0)) return Vec3(1.0, 0.0, 0.0);
  const double v = (d11 * d20 - d01 * d21) / den;
  const double w = (d00 * d21 - d01 * d20) / den;
  Vec3 bary(1.0 - v - w, v, w);
  bary = bary.cwiseMax(0.0);
  return bary / bary.sum();
}
}  // namespace

struct SurfaceLocator::Impl {
  const TriangleMesh& mesh;
  Triangles triangles;
  AabbTree tree;
  explicit Impl(const TriangleMesh& m) : mesh(m) {}
};

SurfaceLocator::SurfaceLocator(const TriangleMesh& mesh) : impl_(std::make_unique<Impl>(mesh))
{
  if (mesh.faces.empty()) throw InputError("the part mesh has no faces", "import a part with triangles");
  Impl& m = *impl_;
  m.triangles.reserve(mesh.faceCount());
  for (const Face& f : mesh.faces)
    m.triangles.emplace_back(toCgal(mesh.vertices[size_t(f[0])]), toCgal(mesh.vertices[size_t(f[1])]),
                             toCgal(mesh.vertices[size_t(f[2])]));
  m.tree.insert(m.triangles.begin(), m.triangles.end());
  m.tree.build();
  // Built now: left to the first query it would be built by several threads at once.
  m.tree.accelerate_distance_queries();
}

SurfaceLocator::~SurfaceLocator() = default;

SurfacePoint SurfaceLocator::closest(const Vec3& q) const
{
  const auto hit = impl_->tree.closest_point_and_primitive(toCgal(q));
  SurfacePoint p;
  p.face = int(hit.second - impl_->triangles.begin());
  const Face& f = impl_->mesh.faces[size_t(p.face)];
  const Vec3 x = toVec(hit.first);
  p.bary = barycentricOf(x, impl_->mesh.vertices[size_t(f[0])], impl_->mesh.vertices[size_t(f[1])],
                         impl_->mesh.vertices[size_t(f[2])]);
  p.position = p.bary[0] * impl_->mesh.vertices[size_t(f[0])] +
               p.bary[1] * impl_->mesh.vertices[size_t(f[1])] +
               p.bary[2] * impl_->mesh.vertices[size_t(f[2])];
  return p;
}

}  // namespace spira::geodesic
