#pragma once

#include <vector>

#include "spira/field/mesh_adjacency.h"
#include "spira/field/symmetric_sparse_matrix.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

// The discrete operators of the thesis, Appendix A.2.
struct CotanLaplacian {
  // -L_C: the P1 finite-element stiffness matrix, positive semi-definite. Entry (i, j) is
  // -(cot a_ij + cot b_ij) / 2 over the angles opposite edge ij; each diagonal entry is minus
  // the sum of the off-diagonal entries of its row. Faces of zero area contribute nothing.
  SymmetricSparseMatrix stiffness;
  // A: barycentric vertex areas (one third of the area of the incident faces), mm^2.
  std::vector<double> vertexArea;
  // h: mean length of the mesh edges, mm.
  double meanEdgeLength = 0.0;
};

CotanLaplacian buildCotanLaplacian(const TriangleMesh& mesh, const MeshAdjacency& adjacency);

// Cotangents of the three corner angles of a face (0 for a face of zero area) and its area.
struct FaceCotangents {
  double cot[3];
  double area;
};
FaceCotangents faceCotangents(const Vec3& p0, const Vec3& p1, const Vec3& p2);

}  // namespace spira
