#ifndef CGAL_EIGEN3_ENABLED
#define CGAL_EIGEN3_ENABLED
#endif

#include "spira/skeleton/mcf_flow.h"

#include <cmath>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mean_curvature_flow_skeletonization.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

namespace spira {

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
    mcf.contract();
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
