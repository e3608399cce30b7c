#include "spira/ui/views/vtk_mesh.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

#include "spira/mesh/triangle_mesh.h"

namespace spira::ui {

vtkSmartPointer<vtkPolyData> toPolyData(const TriangleMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    const Vec3& v = mesh.vertices[i];
    points->SetPoint(static_cast<vtkIdType>(i), v.x(), v.y(), v.z());
  }

  // Fill offsets and connectivity directly: InsertNextCell per face is several times slower on
  // million-triangle parts.
  const auto faceCount = static_cast<vtkIdType>(mesh.faces.size());
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(faceCount + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(3 * faceCount);
  for (vtkIdType f = 0; f < faceCount; ++f) {
    const Face& face = mesh.faces[static_cast<size_t>(f)];
    offsets->SetValue(f, 3 * f);
    for (int k = 0; k < 3; ++k) connectivity->SetValue(3 * f + k, face[static_cast<size_t>(k)]);
  }
  offsets->SetValue(faceCount, 3 * faceCount);
  vtkNew<vtkCellArray> polys;
  polys->SetData(offsets, connectivity);

  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  return poly;
}

vtkSmartPointer<vtkPolyData> toShadedPolyData(const TriangleMesh& mesh)
{
  vtkSmartPointer<vtkPolyData> poly = toPolyData(mesh);
  // Splitting duplicates points at creases; the ids lead per-vertex values (fields) to them.
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName(kVertexIdArray);
  ids->SetNumberOfValues(poly->GetNumberOfPoints());
  for (vtkIdType i = 0; i < poly->GetNumberOfPoints(); ++i) ids->SetValue(i, i);
  poly->GetPointData()->AddArray(ids);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(poly);
  normals->SetFeatureAngle(40.0);
  normals->SplittingOn();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  normals->ComputeCellNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}

}  // namespace spira::ui
