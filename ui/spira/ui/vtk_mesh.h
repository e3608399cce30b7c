#pragma once

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace spira {
struct TriangleMesh;
}

namespace spira::ui {

// The mesh as VTK polygons (points copied, faces as triangles), no normals.
vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh);

// The same with point normals for smooth shading. Normals are split at sharp creases (feature
// angle) so machined edges stay crisp, and they keep the mesh's own orientation: an open part has
// no inside to flip towards.
vtkSmartPointer<vtkPolyData> toShadedPolyData(const TriangleMesh& mesh);

}  // namespace spira::ui
