#pragma once

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace spira {
struct TriangleMesh;
}

namespace spira::ui {

// The mesh as VTK polygons (points copied, faces as triangles), no normals.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

// Name of the point array of toShadedPolyData() holding each point's mesh vertex index.
constexpr const char* kVertexIdArray = "spira_vertex";

// The same with point normals for smooth shading. Normals are split at sharp creases (feature
// angle) so machined edges stay crisp, and they keep the mesh's own orientation: an open part has
// no inside to flip towards. Split points are copies: the kVertexIdArray array names the mesh
// vertex of every point.
vtkSmartPointer<vtkPolyData> toShadedPolyData(const TriangleMesh& mesh);

}  // namespace spira::ui
