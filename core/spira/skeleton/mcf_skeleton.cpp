// Validation, capping and simplification around the mean curvature flow; the flow itself runs in
// its own translation unit (mcf_flow.cpp), which everything here reaches through plain arrays.
#include "spira/skeleton/mcf_skeleton.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>

#include "spira/base/error.h"
#include "spira/mesh/mesh_report.h"
#include "spira/skeleton/capped_surface.h"
#include "spira/skeleton/mcf_flow.h"
#include "spira/skeleton/skeleton_centering.h"
#include "spira/skeleton/skeleton_pruning.h"

namespace spira {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

void requireSkeletonizable(const MeshReport& report)
{
  const std::string hint = "repair the mesh (import with welding, fix the reported defects) and try again";
  if (report.faceCount == 0) throw InputError("the part has no faces: there is nothing to skeletonize", hint);
  if (report.hasIssue(MeshIssueKind::NonFiniteCoordinate) ||
      report.hasIssue(MeshIssueKind::NonManifoldEdge) || report.hasIssue(MeshIssueKind::NonManifoldVertex) ||
      report.hasIssue(MeshIssueKind::InconsistentOrientation))
    throw InputError("the skeleton needs a manifold, consistently oriented mesh, and this one has defects",
                     hint);
  if (report.componentCount != 1)
    throw InputError("the part has " + std::to_string(report.componentCount) +
                         " separate pieces; the skeleton is computed for one connected part",
                     "keep only the piece to plan, or split the file into one part per piece");
  for (const BoundaryLoop& loop : report.boundaryLoops)
    if (!loop.closed)
      throw InputError(
          "a free edge of the part does not close into a loop, so it cannot be capped "
          "for the skeleton",
          hint);
}

SurfaceMesh toSurfaceMesh(const TriangleMesh& mesh)
{
  SurfaceMesh sm;
  std::vector<SurfaceMesh::Vertex_index> ids;
  ids.reserve(mesh.vertexCount());
  for (const Vec3& p : mesh.vertices) ids.push_back(sm.add_vertex(Kernel::Point_3(p.x(), p.y(), p.z())));
  size_t dropped = 0;
  for (const Face& f : mesh.faces) {
    if (f[0] == f[1] || f[1] == f[2] || f[0] == f[2]) {
      ++dropped;
      continue;
    }
    if (sm.add_face(ids[f[0]], ids[f[1]], ids[f[2]]) == SurfaceMesh::null_face()) ++dropped;
  }
  if (dropped)
    throw InputError(std::to_string(dropped) + " faces could not be joined into one surface for the skeleton",
                     "remove duplicate and degenerate faces from the mesh");
  return sm;
}

// The surface as plain arrays for the flow; indices are contiguous once garbage is collected.
FlowSurface toFlowSurface(SurfaceMesh& sm)
{
  sm.collect_garbage();
  FlowSurface out;
  out.vertices.reserve(sm.number_of_vertices());
  for (auto v : sm.vertices()) {
    const auto& p = sm.point(v);
    out.vertices.push_back({p.x(), p.y(), p.z()});
  }
  out.faces.reserve(sm.number_of_faces());
  for (auto f : sm.faces()) {
    std::array<int, 3> face{};
    int k = 0;
    for (auto v : CGAL::vertices_around_face(sm.halfedge(f), sm))
      face[static_cast<size_t>(k++)] = static_cast<int>(v);
    out.faces.push_back(face);
  }
  return out;
}

SkeletonGraph toGraph(const FlowSkeleton& skeleton)
{
  SkeletonGraph g;
  g.nodes.reserve(skeleton.nodes.size());
  for (const auto& p : skeleton.nodes) g.nodes.emplace_back(p[0], p[1], p[2]);
  for (const auto& e : skeleton.edges) g.edges.push_back({e[0], e[1]});
  return g;
}

}  // namespace

SkeletonResult computeCurveSkeleton(const TriangleMesh& mesh, const SkeletonOptions& options,
                                    Progress& progress)
{
  if (options.maxIterations < 1)
    throw InputError("the skeleton needs at least one contraction step", "raise the iteration limit");
  if (!(options.areaVariation > 0 && options.areaVariation < 1))
    throw InputError("the skeleton's convergence threshold must lie between 0 and 1, not " +
                         std::to_string(options.areaVariation),
                     "use a small fraction such as 1e-4");
  const MeshReport report = validateMesh(mesh);
  requireSkeletonizable(report);

  SkeletonResult out;
  const CappedSurface capped = capBoundaryLoops(mesh, report.boundaryLoops);
  out.capsAdded = capped.capsAdded;
  SurfaceMesh sm = toSurfaceMesh(capped.mesh);
  if (!CGAL::is_closed(sm))
    throw InputError("the part could not be closed for the skeleton (a free edge was left open)",
                     "repair the mesh's free edges and try again");

  // The skeleton is coarse by nature: a simplified surface gives the same curve much faster, and
  // the nodes are re-centred on the full-resolution part afterwards.
  if (options.maxFaces > 0 && sm.number_of_faces() > options.maxFaces) {
    progress.report(0.0, "skeleton: simplifying");
    namespace SMS = CGAL::Surface_mesh_simplification;
    SMS::Count_stop_predicate<SurfaceMesh> stop(options.maxFaces * 3 / 2);
    // Shortest edges first, merged at their midpoints: the surface coarsens evenly and keeps
    // well-shaped triangles, which the flow's cotangent weights need (a shape-preserving cost
    // would happily make long slivers on flat and cylindrical walls).
    SMS::edge_collapse(sm, stop,
                       CGAL::parameters::get_cost(SMS::Edge_length_cost<SurfaceMesh>())
                           .get_placement(SMS::Midpoint_placement<SurfaceMesh>()));
    sm.collect_garbage();
  }
  out.facesContracted = sm.number_of_faces();
  progress.report(0.05, "skeleton: medial poles");
  FlowSettings flow;
  flow.maxIterations = options.maxIterations;
  flow.areaVariation = options.areaVariation;
  flow.mediallyCentered = options.mediallyCentered;
  flow.qualitySpeedTradeoff = options.qualitySpeedTradeoff;
  flow.medialSpeedTradeoff = options.medialSpeedTradeoff;
  const FlowSkeleton skeleton = runMeanCurvatureFlow(
      toFlowSurface(sm), flow, [&] { progress.checkCancel(); },
      [&](double areaRatio) {
        // The area falls roughly geometrically; its log tells how far along the flow is.
        const double fraction = std::log(std::max(areaRatio, 1e-300)) / std::log(options.areaVariation);
        progress.report(std::clamp(fraction, 0.05, 0.95), "skeleton: contraction");
      });
  out.iterations = skeleton.iterations;
  out.converged = skeleton.converged;
  if (!out.converged)
    out.warnings.push_back("the skeleton's contraction stopped at the limit of " +
                           std::to_string(options.maxIterations) +
                           " steps before it settled; the skeleton may be rough");
  if (skeleton.nodes.empty())
    throw AlgorithmError("the mean curvature flow left no skeleton for this part",
                         "check that the part is a thin-walled shell and not a flat sheet");
  const double tolerance =
      options.monotoneTolerance >= 0 ? options.monotoneTolerance : 0.02 * report.bounds.diagonal();
  SkeletonGraph graph = toGraph(skeleton);
  if (options.pruneSpurs) out.spursPruned = pruneSpurs(graph, mesh);
  if (options.centreInSections) out.nodesCentred = centreInCrossSections(graph, mesh, progress);
  out.skeleton = analyseSkeleton(std::move(graph), tolerance);
  progress.report(1.0, "skeleton");
  return out;
}

}  // namespace spira
