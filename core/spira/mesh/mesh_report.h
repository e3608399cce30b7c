#pragma once

#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "spira/mesh/triangle_mesh.h"

namespace spira {

enum class MeshIssueKind {
  NonFiniteCoordinate,      // NaN or infinite vertex coordinate
  DegenerateFace,           // repeated vertex index or zero area
  DuplicateFace,            // same three vertices as an earlier face
  NonManifoldEdge,          // edge shared by more than two faces
  NonManifoldVertex,        // vertex whose incident faces form more than one fan
  InconsistentOrientation,  // two faces traverse their shared edge in the same direction
};

const char* meshIssueName(MeshIssueKind kind);  // stable snake_case name, used in JSON

// One kind of defect: how many, and where (the first few, so a report stays short).
struct MeshIssue {
  MeshIssueKind kind;
  size_t count = 0;
  std::vector<int> elements;   // face ids (face issues), vertex ids (vertex issues) or the first face of an edge
  std::vector<Vec3> positions; // a representative position for each listed element
};

// A closed chain of boundary edges, vertices in order (first vertex not repeated at the end).
// The loop runs so that the mesh lies on its left when seen from outside (the direction the
// faces' boundary edges run).
struct BoundaryLoop {
  std::vector<int> vertices;
  double length = 0.0;
  double zMin = 0.0, zMax = 0.0;
};

enum class PartClass { Open, Closed, Unsupported };
const char* partClassName(PartClass c);  // "open", "closed", "unsupported"

struct MeshReport {
  size_t vertexCount = 0;
  size_t faceCount = 0;
  size_t edgeCount = 0;
  BoundingBox bounds;
  double area = 0.0;
  double meanEdgeLength = 0.0;
  std::vector<MeshIssue> issues;  // only kinds with count > 0
  std::vector<BoundaryLoop> boundaryLoops;  // sorted by zMin ascending
  size_t componentCount = 0;
  PartClass partClass = PartClass::Unsupported;
  std::string classReason;  // why the part is open, closed or unsupported, in plain words

  bool hasIssue(MeshIssueKind k) const;
  size_t issueCount(MeshIssueKind k) const;
  // No defect that stops planning (non-finite, non-manifold, inconsistent orientation).
  bool isPlannable() const;
  std::string toText() const;
  nlohmann::json toJson() const;
};

// Maximum number of elements/positions listed per issue.
constexpr size_t kMaxListedIssueElements = 10;

// Validates a welded mesh: every defect is counted, boundary loops are extracted and ordered,
// connected components counted and the part classified (2 loops: open, 1: closed, else unsupported).
MeshReport validateMesh(const TriangleMesh& mesh);

}  // namespace spira
