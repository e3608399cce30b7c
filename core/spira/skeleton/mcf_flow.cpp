#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include "spira/skeleton/mcf_flow.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

namespace spira {

namespace {

// Numbers the meso-skeleton's halfedges in list order. The list order follows the mesh's history
// (creation and removal of elements), never the addresses the allocator chose.
template <class Mesh>
void numberHalfedges(Mesh& mesh)
{
  std::size_t i = 0;
  for (auto h : halfedges(mesh)) h->id() = i++;
}

// CGAL's collapse_edges(), with its queues of short edges ordered by halfedge number instead of by
// halfedge address. CGAL keeps the queue in a std::set<edge_descriptor>, which compares the
// addresses of the polyhedron's halfedges: the collapses then ran in whatever order the heap laid
// the halfedges out, which differs between runs, between two plans in one process and with the
// thread count, and the skeleton (and every envelope plan projected towards it) changed with it.
// Everything else is CGAL's step as is: the same edges, the same link condition, the kept vertex at
// the midpoint, the same bookkeeping of input vertices, fixed flags and poles.
template <class Flow>
std::size_t collapseShortEdges(Flow& flow)
{
  using Mesh = typename Flow::Meso_skeleton;
  using Edge = typename boost::graph_traits<Mesh>::edge_descriptor;
  using Vertex = typename boost::graph_traits<Mesh>::vertex_descriptor;
  // The flow only hands out a const view of its meso-skeleton, which is its own non-const member;
  // changing it between the flow's steps is what its collapse_edges() does.
  Mesh& mesh = const_cast<Mesh&>(flow.meso_skeleton());
  numberHalfedges(mesh);
  // An edge's number is its smaller halfedge number; collapses only remove halfedges, so the
  // numbers of the edges left stay put while the queues hold them.
  const auto number = [&](const Edge& e) {
    const auto h = halfedge(e, mesh);
    return std::min(h->id(), opposite(h, mesh)->id());
  };
  using Queue = std::map<std::size_t, Edge>;
  const auto add = [&](Queue& q, const Edge& e) { q.emplace(number(e), e); };
  const auto drop = [&](Queue& q, const Edge& e) { q.erase(number(e)); };
  const double minLength2 = flow.min_edge_length() * flow.min_edge_length();
  const auto shouldCollapse = [&](const Edge& e) {
    const auto h = halfedge(e, mesh);
    const Vertex vi = source(h, mesh), vj = target(h, mesh);
    if (vi->is_fixed && vj->is_fixed) return false;
    return CGAL::squared_distance(vi->point(), vj->point()) < minLength2;
  };

  Queue toCollapse, invalid;
  for (Edge e : edges(mesh))
    if (shouldCollapse(e)) add(toCollapse, e);
  std::size_t count = 0, previous = 0;
  do {
    previous = count;
    while (!toCollapse.empty()) {
      const Edge e = toCollapse.begin()->second;
      toCollapse.erase(toCollapse.begin());
      if (!shouldCollapse(e)) continue;
      if (!CGAL::Euler::does_satisfy_link_condition(e, mesh)) {
        add(invalid, e);
        continue;
      }
      const auto h = halfedge(e, mesh);
      const Vertex vi = source(h, mesh), vj = target(h, mesh);
      const auto p = CGAL::midpoint(vi->point(), vj->point());
      // The collapse removes these two edges besides e.
      const Edge before = edge(prev(h, mesh), mesh),
                 beforeOpposite = edge(prev(opposite(h, mesh), mesh), mesh);
      drop(toCollapse, before);
      drop(toCollapse, beforeOpposite);
      drop(invalid, e);
      drop(invalid, before);
      drop(invalid, beforeOpposite);
      // The mesh is closed: the target of h is the vertex kept.
      vj->point() = p;
      vj->vertices.insert(vj->vertices.end(), vi->vertices.begin(), vi->vertices.end());
      if (vi->is_fixed) vj->is_fixed = true;
      if (flow.is_medially_centered() &&
          CGAL::squared_distance(vi->pole, p) < CGAL::squared_distance(vj->pole, p))
        vj->pole = vi->pole;
      const Vertex kept = CGAL::Euler::collapse_edge(e, mesh);
      for (Edge out : out_edges(kept, mesh))
        if (shouldCollapse(out)) add(toCollapse, out);
      ++count;
    }
    if (count == previous) break;
    toCollapse.swap(invalid);
  } while (!toCollapse.empty());
  // CGAL's next steps read per-halfedge data by halfedge number, in list order.
  numberHalfedges(mesh);
  return count;
}

}  // namespace

FlowSkeleton runMeanCurvatureFlow(const FlowSurface& surface, const FlowSettings& settings,
                                  const std::function<void()>& beforeStep,
                                  const std::function<void(double)>& afterStep)
{
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
  using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<SurfaceMesh>;

  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> ids;
  ids.reserve(surface.vertices.size());
  for (const auto& v : surface.vertices) ids.push_back(sm.add_vertex(Kernel::Point_3(v[0], v[1], v[2])));
  for (const auto& f : surface.faces) sm.add_face(ids[f[0]], ids[f[1]], ids[f[2]]);

  FlowSkeleton out;
  Skeletonization mcf(sm);
  mcf.set_is_medially_centered(settings.mediallyCentered);
  mcf.set_quality_speed_tradeoff(settings.qualitySpeedTradeoff);
  mcf.set_medially_centered_speed_tradeoff(settings.medialSpeedTradeoff);
  mcf.set_area_variation_factor(settings.areaVariation);
  mcf.set_max_iterations(settings.maxIterations);

  // contract_until_convergence(), one step at a time so that the caller can report and cancel.
  const double originalArea = CGAL::Polygon_mesh_processing::area(sm);
  double lastArea = 0.0;
  while (out.iterations < settings.maxIterations) {
    beforeStep();
    // mcf.contract(), with a collapse whose order does not depend on memory addresses.
    mcf.contract_geometry();
    collapseShortEdges(mcf);
    mcf.split_faces();
    mcf.detect_degeneracies();
    ++out.iterations;
    const double area = CGAL::Polygon_mesh_processing::area(mcf.meso_skeleton());
    afterStep(area / originalArea);
    if (std::abs(lastArea - area) / originalArea < settings.areaVariation) {
      out.converged = true;
      break;
    }
    lastArea = area;
  }

  Skeletonization::Skeleton skeleton;
  mcf.convert_to_skeleton(skeleton);
  out.nodes.reserve(boost::num_vertices(skeleton));
  for (auto v : CGAL::make_range(boost::vertices(skeleton))) {
    const auto& p = skeleton[v].point;
    out.nodes.push_back({p.x(), p.y(), p.z()});
  }
  for (auto e : CGAL::make_range(boost::edges(skeleton)))
    out.edges.push_back(
        {static_cast<int>(boost::source(e, skeleton)), static_cast<int>(boost::target(e, skeleton))});
  return out;
}

}  // namespace spira
