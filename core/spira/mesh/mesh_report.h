#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/mesh/boundary_loops.h"
#include "spira/mesh/triangle_mesh.h"

namespace spira {

enum class MeshIssueKind {
  NonFiniteCoordinate,  // NaN or infinite vertex coordinate
  DegenerateFace,       // repeated vertex index or zero area
  DuplicateFace,        // same three vertices as an earlier face (in any order)
  NonManifoldEdge,      // edge shared by more than two faces
  NonManifoldVertex,    // vertex whose incident faces form more than one fan
  // Face that traverses a shared edge in the same direction as its neighbour. Faces are counted,
  // not edges: in each patch of faces joined by two-face edges, the smaller set of faces whose
  // flip would make the patch consistent (one flipped face is one finding, not three edges).
  InconsistentOrientation,
};

const char* meshIssueName(MeshIssueKind kind);  // stable snake_case name, used in JSON

// One kind of defect: how many, and where (the first few, so a report stays short).
struct MeshIssue {
  MeshIssueKind kind;
  size_t count = 0;
  // Lowest ids first: face ids (face issues), vertex ids (vertex issues) or the first face of an edge.
  std::vector<int> elements;
  // A representative position for each listed element: the vertex, the face centroid or the edge midpoint.
  std::vector<Vec3> positions;
};

enum class PartClass { Open, Closed, Unsupported };
const char* partClassName(PartClass c);  // "open", "closed", "unsupported"

struct MeshReport {
  size_t vertexCount = 0;
  size_t faceCount = 0;
  size_t edgeCount = 0;  // undirected edges of the topology faces (see validateMesh)
  BoundingBox bounds;    // of the finite vertices
  double area = 0.0;     // mm^2, finite faces
  double meanEdgeLength = 0.0;
  std::vector<MeshIssue> issues;            // only kinds with count > 0, in MeshIssueKind order
  std::vector<BoundaryLoop> boundaryLoops;  // sorted by zMin ascending
  size_t componentCount = 0;
  PartClass partClass = PartClass::Unsupported;
  std::string classReason;  // why the part is open, closed or unsupported, in plain words

  bool hasIssue(MeshIssueKind k) const;
  size_t issueCount(MeshIssueKind k) const;
  const MeshIssue* issue(MeshIssueKind k) const;  // nullptr when the mesh has none of that kind
  // No defect that stops planning (non-finite, non-manifold, inconsistent orientation). The part
  // class is separate: an Unsupported part may be plannable as a mesh but not as a part.
  // No defect stops planning (the class may still be one Spira refuses).
  bool isPlannable() const;
  // One or two boundary loops but no wall between them: every vertex lies on the edge (a single
  // triangle, a flat strip or fan). No strategy plans such a part, whatever its defects.
  bool hasNoWall() const;
  // partClassName(), or "multi_branch" for one connected wall with more than two free edges.
  const char* className() const;
  std::string toText() const;
  nlohmann::json toJson() const;
};

// Maximum number of elements/positions listed per issue.
constexpr size_t kMaxListedIssueElements = 10;

// A face is degenerate by area when area <= kDegenerateAreaRelative * diagonal^2 (bounding box):
// well above rounding noise of collinear corners (about 1e-16 * diagonal^2), far below any real
// triangle (one with two legs of 1e-6 * diagonal has 50 times that area).
constexpr double kDegenerateAreaRelative = 1e-14;

// Validates a welded mesh: every defect is counted, boundary loops are extracted and ordered,
// connected components counted and the part classified (2 loops: open, 1: closed, else unsupported).
//
// Topology (edges, boundary loops, non-manifold checks, orientation, components) is analysed on
// the "topology faces": all faces except those with a repeated vertex index and the later copies
// of duplicate faces. Those are reported as degenerate or duplicate and would otherwise also show
// up as spurious non-manifold edges. Zero-area faces with three distinct vertices stay in: they
// often close a crack (a T-junction) and leaving them out would open a false hole.
// Orientation is only compared across edges with exactly two faces (non-manifold edges are
// reported as such). Components are vertex-connected: faces sharing only a vertex are one part.
// Throws InputError when a face uses a vertex index that does not exist.
MeshReport validateMesh(const TriangleMesh& mesh);

}  // namespace spira
