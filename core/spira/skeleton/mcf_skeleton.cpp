// The one translation unit that includes CGAL's mean curvature flow skeletonization (slow to
// compile); everything else in Spira sees only mcf_skeleton.h.
// GCC 12 flags std::map internals inlined into CGAL's collapse_short_edges() as dangling
// pointers (a known false positive of -Wdangling-pointer); the warning is about the library's
// code, so it is silenced for this unit only.
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
#pragma GCC diagnostic ignored "-Wdangling-pointer"
#endif
#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include "spira/skeleton/mcf_skeleton.h"

#include <algorithm>
#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Edge_length_cost.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Midpoint_placement.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>

#include "spira/base/error.h"
#include "spira/mesh/mesh_report.h"
#include "spira/skeleton/capped_surface.h"
#include "spira/skeleton/skeleton_centering.h"
#include "spira/skeleton/skeleton_pruning.h"

namespace spira {

namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<SurfaceMesh>;

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

SkeletonGraph toGraph(const Skeletonization::Skeleton& skeleton)
{
  SkeletonGraph g;
  g.nodes.reserve(boost::num_vertices(skeleton));
  for (auto v : CGAL::make_range(boost::vertices(skeleton))) {
    const auto& p = skeleton[v].point;
    g.nodes.emplace_back(p.x(), p.y(), p.z());
  }
  for (auto e : CGAL::make_range(boost::edges(skeleton)))
    g.edges.push_back(
        {static_cast<int>(boost::source(e, skeleton)), static_cast<int>(boost::target(e, skeleton))});
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
  Skeletonization mcf(sm);
  mcf.set_is_medially_centered(options.mediallyCentered);
  mcf.set_quality_speed_tradeoff(options.qualitySpeedTradeoff);
  mcf.set_medially_centered_speed_tradeoff(options.medialSpeedTradeoff);
  mcf.set_area_variation_factor(options.areaVariation);
  mcf.set_max_iterations(options.maxIterations);

  // contract_until_convergence(), one step at a time so that the loop can report and be cancelled.
  const double originalArea = CGAL::Polygon_mesh_processing::area(sm);
  double lastArea = 0.0;
  while (out.iterations < options.maxIterations) {
    progress.checkCancel();
    mcf.contract();
    ++out.iterations;
    const double area = CGAL::Polygon_mesh_processing::area(mcf.meso_skeleton());
    const double change = std::abs(lastArea - area) / originalArea;
    // The area falls roughly geometrically; its log tells how far along the flow is.
    const double fraction = std::log(std::max(area, 1e-300) / originalArea) / std::log(options.areaVariation);
    progress.report(std::clamp(fraction, 0.05, 0.95), "skeleton: contraction");
    if (change < options.areaVariation) {
      out.converged = true;
      break;
    }
    lastArea = area;
  }
  if (!out.converged)
    out.warnings.push_back("the skeleton's contraction stopped at the limit of " +
                           std::to_string(options.maxIterations) +
                           " steps before it settled; the skeleton may be rough");

  Skeletonization::Skeleton skeleton;
  mcf.convert_to_skeleton(skeleton);
  if (boost::num_vertices(skeleton) == 0)
    throw AlgorithmError("the mean curvature flow left no skeleton for this part",
                         "check that the part is a thin-walled shell and not a flat sheet");
  const double tolerance =
      options.monotoneTolerance >= 0 ? options.monotoneTolerance : 0.005 * report.bounds.diagonal();
  SkeletonGraph graph = toGraph(skeleton);
  if (options.pruneSpurs) out.spursPruned = pruneSpurs(graph, mesh);
  if (options.centreInSections) out.nodesCentred = centreInCrossSections(graph, mesh, progress);
  out.skeleton = analyseSkeleton(std::move(graph), tolerance);
  progress.report(1.0, "skeleton");
  return out;
}

}  // namespace spira
