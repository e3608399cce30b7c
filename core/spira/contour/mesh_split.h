#pragma once

#include <cstdint>
#include <vector>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

// Where a vertex of a refined mesh comes from: position = (1 - t) x[v0] + t x[v1] of the mesh
// before the cut (v0 == v1 and t = 0 for a vertex that was already there).
struct VertexOrigin {
  int v0 = -1, v1 = -1;
  double t = 0.0;
};

// A mesh refined along one iso-line of a per-vertex field, so that every face lies on one side.
struct LevelCut {
  TriangleMesh mesh;                 // the input's vertices first (same ids), then the new ones
  std::vector<VertexOrigin> origin;  // one per vertex of `mesh`
  std::vector<std::uint8_t> above;   // per face: 1 on the side field >= level, 0 below
  std::vector<int> parentFace;       // per face: the input face it is part of
  size_t newVertexCount() const;
};

// Cuts the faces selected by `faceMask` (all when null) along field = level: every face whose
// corners lie on both sides is split into triangles on either side, with one shared vertex per cut
// edge, so both sides come out as manifold pieces whose boundary runs along the iso-line. Faces keep
// their orientation; faces outside the mask are copied as they are (their `above` is 0).
//
// A corner counts as ON the level when it is closer to it than `snap` (0.05 by default) times the
// largest field step to a neighbour across the level: the iso-line then passes through the vertex
// instead of making a sliver next to it, so every new vertex sits at t in (snap, 1 - snap) on its
// edge. Faces with corners on the level and none below count as above.
// Throws InputError when the field does not have one finite value per vertex of the masked faces.
LevelCut cutAlongLevel(const TriangleMesh& mesh, const std::vector<double>& field, double level,
                       const std::vector<std::uint8_t>* faceMask = nullptr, double snap = 0.05);

// Per-vertex values carried onto the refined mesh by linear interpolation along the cut edges.
std::vector<double> carryToCut(const LevelCut& cut, const std::vector<double>& values);

// The faces `faceIds` of `mesh` as a mesh of their own, vertices renumbered in order of first use.
struct SubMesh {
  TriangleMesh mesh;
  std::vector<int> parentVertex;  // sub-mesh vertex -> vertex of the full mesh
  std::vector<int> parentFace;    // sub-mesh face -> face of the full mesh
};
SubMesh extractFaces(const TriangleMesh& mesh, const std::vector<int>& faceIds);

// Labels the faces with `faceMask` != 0 by edge-connected component (faces touching only at a
// vertex are apart, so branches that meet at a point separate), -1 outside the mask. Components
// are numbered by their lowest face id. Returns the number of components.
int faceComponents(const TriangleMesh& mesh, const std::vector<std::uint8_t>& faceMask,
                   std::vector<int>& component);

}  // namespace spira
