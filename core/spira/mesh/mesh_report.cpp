#include "spira/mesh/mesh_report.h"

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "spira/base/number_text.h"

namespace spira {

namespace {

std::string point(const Vec3& p)
{
  return "(" + significantText(p.x(), 6) + ", " + significantText(p.y(), 6) + ", " +
         significantText(p.z(), 6) + ")";
}

// Human-readable issue names for the text report, singular and plural; meshIssueName() gives the
// stable JSON keys.
std::string issueLabel(MeshIssueKind kind, size_t count)
{
  const bool one = count == 1;
  switch (kind) {
    case MeshIssueKind::NonFiniteCoordinate:
      return one ? "vertex with a non-finite coordinate" : "vertices with non-finite coordinates";
    case MeshIssueKind::DegenerateFace:
      return std::string(one ? "degenerate face" : "degenerate faces") + " (repeated vertex or zero area)";
    case MeshIssueKind::DuplicateFace:
      return one ? "duplicate face" : "duplicate faces";
    case MeshIssueKind::NonManifoldEdge:
      return std::string(one ? "non-manifold edge" : "non-manifold edges") + " (more than two faces)";
    case MeshIssueKind::NonManifoldVertex:
      return std::string(one ? "non-manifold vertex" : "non-manifold vertices") +
             " (faces touch only at the vertex)";
    case MeshIssueKind::InconsistentOrientation:
      return std::string(one ? "face" : "faces") +
             " with inconsistent orientation (flipped against the neighbours)";
  }
  return "unknown issue";
}

const char* elementWord(MeshIssueKind kind)
{
  switch (kind) {
    case MeshIssueKind::NonFiniteCoordinate:
    case MeshIssueKind::NonManifoldVertex:
      return "vertex";
    case MeshIssueKind::NonManifoldEdge:
      return "edge of face";
    default:
      return "face";
  }
}

nlohmann::json jsonPoint(const Vec3& p)
{
  return nlohmann::json::array({p.x(), p.y(), p.z()});
}

}  // namespace

const char* meshIssueName(MeshIssueKind kind)
{
  switch (kind) {
    case MeshIssueKind::NonFiniteCoordinate:
      return "non_finite_coordinate";
    case MeshIssueKind::DegenerateFace:
      return "degenerate_face";
    case MeshIssueKind::DuplicateFace:
      return "duplicate_face";
    case MeshIssueKind::NonManifoldEdge:
      return "non_manifold_edge";
    case MeshIssueKind::NonManifoldVertex:
      return "non_manifold_vertex";
    case MeshIssueKind::InconsistentOrientation:
      return "inconsistent_orientation";
  }
  return "unknown";
}

const char* partClassName(PartClass c)
{
  switch (c) {
    case PartClass::Open:
      return "open";
    case PartClass::Closed:
      return "closed";
    case PartClass::Unsupported:
      return "unsupported";
  }
  return "unsupported";
}

const MeshIssue* MeshReport::issue(MeshIssueKind k) const
{
  for (const MeshIssue& i : issues)
    if (i.kind == k) return &i;
  return nullptr;
}

bool MeshReport::hasIssue(MeshIssueKind k) const
{
  return issueCount(k) > 0;
}

size_t MeshReport::issueCount(MeshIssueKind k) const
{
  const MeshIssue* i = issue(k);
  return i ? i->count : 0;
}

const char* MeshReport::className() const
{
  if (partClass == PartClass::Unsupported && componentCount == 1 && boundaryLoops.size() > 2)
    return "multi_branch";
  return partClassName(partClass);
}

bool MeshReport::hasNoWall() const
{
  return !boundaryLoops.empty() && boundaryLoops.size() <= 2 && partClass == PartClass::Unsupported;
}

bool MeshReport::isPlannable() const
{
  // A mesh whose every face is degenerate has no surface at all.
  const bool noSurface = faceCount > 0 && issueCount(MeshIssueKind::DegenerateFace) >= faceCount;
  return !noSurface && !hasIssue(MeshIssueKind::NonFiniteCoordinate) &&
         !hasIssue(MeshIssueKind::NonManifoldEdge) && !hasIssue(MeshIssueKind::NonManifoldVertex) &&
         !hasIssue(MeshIssueKind::InconsistentOrientation);
}

std::string MeshReport::toText() const
{
  std::ostringstream s;
  s << "Mesh: " << vertexCount << " vertices, " << faceCount << " faces, " << edgeCount << " edges\n";
  if (bounds.empty()) {
    s << "Bounding box: empty\n";
  } else {
    const Vec3 size = bounds.size();
    s << "Bounding box: x " << significantText(bounds.min.x(), 6) << " .. "
      << significantText(bounds.max.x(), 6) << ", y " << significantText(bounds.min.y(), 6) << " .. "
      << significantText(bounds.max.y(), 6) << ", z " << significantText(bounds.min.z(), 6) << " .. "
      << significantText(bounds.max.z(), 6) << " mm (size " << significantText(size.x(), 6) << " x "
      << significantText(size.y(), 6) << " x " << significantText(size.z(), 6) << " mm)\n";
  }
  s << "Surface area: " << significantText(area, 6) << " mm^2; mean edge length "
    << significantText(meanEdgeLength, 6) << " mm\n";
  if (issues.empty()) s << "Issues: none\n";
  for (const MeshIssue& i : issues) {
    s << "Issue: " << i.count << " " << issueLabel(i.kind, i.count);
    if (i.count > i.elements.size()) s << "; the first " << i.elements.size() << ":";
    s << "\n";
    for (size_t k = 0; k < i.elements.size(); ++k)
      s << "  " << elementWord(i.kind) << " " << i.elements[k] << " at " << point(i.positions[k]) << " mm\n";
  }
  s << "Boundary loops: " << boundaryLoops.size() << "\n";
  for (size_t k = 0; k < boundaryLoops.size(); ++k) {
    const BoundaryLoop& l = boundaryLoops[k];
    s << "  loop " << k + 1 << ": " << l.vertices.size() << " vertices, length "
      << significantText(l.length, 6) << " mm, z " << significantText(l.zMin, 6) << " .. "
      << significantText(l.zMax, 6) << " mm" << (l.closed ? "" : " (not closed)") << "\n";
  }
  s << "Connected components: " << componentCount << "\n";
  s << "Part class: " << className() << " - " << classReason << "\n";
  s << "Mesh defects that stop planning: " << (isPlannable() ? "none" : "yes (see the issues above)") << "\n";
  if (hasNoWall()) s << "Plannable: no, the part has no wall (see its class above)\n";
  return s.str();
}

nlohmann::json MeshReport::toJson() const
{
  nlohmann::json j;
  j["vertex_count"] = vertexCount;
  j["face_count"] = faceCount;
  j["edge_count"] = edgeCount;
  j["bounds_mm"] = bounds.empty()
                       ? nlohmann::json(nullptr)
                       : nlohmann::json{{"min", jsonPoint(bounds.min)}, {"max", jsonPoint(bounds.max)}};
  j["area_mm2"] = area;
  j["mean_edge_length_mm"] = meanEdgeLength;
  nlohmann::json list = nlohmann::json::array();
  for (const MeshIssue& i : issues) {
    nlohmann::json positions = nlohmann::json::array();
    for (const Vec3& p : i.positions) positions.push_back(jsonPoint(p));  // NaN is written as null
    list.push_back({{"kind", meshIssueName(i.kind)},
                    {"count", i.count},
                    {"elements", i.elements},
                    {"positions_mm", std::move(positions)}});
  }
  j["issues"] = std::move(list);
  nlohmann::json loops = nlohmann::json::array();
  for (const BoundaryLoop& l : boundaryLoops)
    loops.push_back({{"vertex_count", l.vertices.size()},
                     {"length_mm", l.length},
                     {"z_min_mm", l.zMin},
                     {"z_max_mm", l.zMax},
                     {"closed", l.closed}});
  j["boundary_loops"] = std::move(loops);
  j["component_count"] = componentCount;
  j["part_class"] = className();
  j["class_reason"] = classReason;
  j["plannable"] = isPlannable() && !hasNoWall();
  return j;
}

}  // namespace spira
