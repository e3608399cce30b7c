#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mesh/mesh_test_shapes.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"
#include "spira/mesh/mesh_weld.h"

using namespace spira;
using test::issueKinds;

namespace {

const int kSeg = 24, kRings = 6;
const double kR = 15.0, kH = 30.0;

TriangleMesh cylinder()
{
  return makeOpenCylinder(kR, kH, kSeg, kRings);
}

// Index of face (v(i,j), v(i,j+1), v(i+1,j+1)) of the open cylinder: the first of quad (i, j).
int quadFace(int i, int j)
{
  return 2 * (i * kSeg + j);
}

double polygonPerimeter(int n, double r)
{
  return n * 2.0 * r * std::sin(kPi / n);
}

// Signed area of a loop projected on XY: positive when counter-clockwise seen from above.
double signedAreaXY(const TriangleMesh& m, const BoundaryLoop& l)
{
  double a = 0.0;
  for (size_t i = 0; i < l.vertices.size(); ++i) {
    const Vec3& p = m.vertices[l.vertices[i]];
    const Vec3& q = m.vertices[l.vertices[(i + 1) % l.vertices.size()]];
    a += 0.5 * (p.x() * q.y() - q.x() * p.y());
  }
  return a;
}

}  // namespace

TEST(Validate, TetrahedronIsWatertightAndUnsupported)
{
  const MeshReport r = validateMesh(makeTetrahedron(10.0));
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.vertexCount, 4u);
  EXPECT_EQ(r.faceCount, 4u);
  EXPECT_EQ(r.edgeCount, 6u);
  EXPECT_TRUE(r.boundaryLoops.empty());
  EXPECT_EQ(r.componentCount, 1u);
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_EQ(r.classReason.rfind("0 boundary loops: the mesh is watertight", 0), 0u) << r.classReason;
  EXPECT_TRUE(r.isPlannable());
  EXPECT_NEAR(r.meanEdgeLength, 10.0, 1e-12);
  EXPECT_NEAR(r.area, std::sqrt(3.0) * 100.0, 1e-10);
}

TEST(Validate, OpenCylinderHasTwoLoopsAtBaseAndRim)
{
  const TriangleMesh m = cylinder();
  const MeshReport r = validateMesh(m);
  EXPECT_TRUE(r.issues.empty()) << r.toText();
  EXPECT_EQ(r.partClass, PartClass::Open);
  EXPECT_TRUE(r.isPlannable());
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  const BoundaryLoop& base = r.boundaryLoops[0];
  const BoundaryLoop& rim = r.boundaryLoops[1];
  EXPECT_EQ(base.vertices.size(), static_cast<size_t>(kSeg));
  EXPECT_TRUE(base.closed && rim.closed);
  EXPECT_EQ(base.zMin, 0.0);
  EXPECT_EQ(base.zMax, 0.0);
  EXPECT_EQ(rim.zMin, kH);
  EXPECT_EQ(rim.zMax, kH);
  EXPECT_NEAR(base.length, polygonPerimeter(kSeg, kR), 1e-10);
  EXPECT_NEAR(rim.length, 2.0 * kPi * kR, 2.0 * kPi * kR * 0.01);  // 24 segments: within 1 %
  // The mesh lies on the loop's left seen from outside: counter-clockwise at the base, clockwise at the rim.
  EXPECT_GT(signedAreaXY(m, base), 0.0);
  EXPECT_LT(signedAreaXY(m, rim), 0.0);
  EXPECT_EQ(r.componentCount, 1u);
}

TEST(Validate, FineCylinderLoopLengthsWithinTenthOfAPercent)
{
  const MeshReport r = validateMesh(makeOpenCylinder(kR, kH, 256, 4));
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  for (const BoundaryLoop& l : r.boundaryLoops) EXPECT_NEAR(l.length, 2.0 * kPi * kR, 1e-3 * 2.0 * kPi * kR);
}

TEST(Validate, HemisphereIsClosed)
{
  const MeshReport r = validateMesh(makeHemisphere(20.0, 64, 16));
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.partClass, PartClass::Closed);
  ASSERT_EQ(r.boundaryLoops.size(), 1u);
  EXPECT_EQ(r.boundaryLoops[0].zMax, 0.0);
  EXPECT_NEAR(r.boundaryLoops[0].length, 2.0 * kPi * 20.0, 1e-3 * 2.0 * kPi * 20.0);
  EXPECT_TRUE(r.isPlannable());
}

TEST(Validate, BowTieReportsExactlyTheSharedVertex)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, -0.5, 0), Vec3(1, 0.5, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0)};
  m.faces = {{0, 1, 2}, {0, 3, 4}};
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::NonManifoldVertex});
  const MeshIssue& i = *r.issue(MeshIssueKind::NonManifoldVertex);
  EXPECT_EQ(i.count, 1u);
  EXPECT_EQ(i.elements, std::vector<int>{0});
  EXPECT_EQ(i.positions[0], Vec3(0, 0, 0));
  EXPECT_FALSE(r.isPlannable());
  // Each wing keeps its own closed boundary loop even though both pass through vertex 0.
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  for (const BoundaryLoop& l : r.boundaryLoops) {
    EXPECT_TRUE(l.closed);
    EXPECT_EQ(l.vertices.size(), 3u);
    EXPECT_NEAR(l.length, 1.0 + 2.0 * std::sqrt(1.25), 1e-12);
  }
  EXPECT_EQ(r.componentCount, 1u);  // vertex-connected
}

TEST(Validate, HourglassOfTwoConesHasOneNonManifoldVertex)
{
  const TriangleMesh lower = makeRevolved({{10.0, 0.0}, {5.0, 5.0}, {0.0, 10.0}}, 16);
  const TriangleMesh upper = makeRevolved({{0.0, 10.0}, {5.0, 15.0}, {10.0, 20.0}}, 16);
  const TriangleMesh m = weldVertices(test::merged(lower, upper));
  ASSERT_EQ(m.vertexCount(), lower.vertexCount() + upper.vertexCount() - 1);
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::NonManifoldVertex}) << r.toText();
  EXPECT_EQ(r.issueCount(MeshIssueKind::NonManifoldVertex), 1u);
  EXPECT_EQ(r.issue(MeshIssueKind::NonManifoldVertex)->positions[0], Vec3(0, 0, 10));
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  EXPECT_EQ(r.boundaryLoops[0].zMax, 0.0);
  EXPECT_EQ(r.boundaryLoops[1].zMin, 20.0);
  EXPECT_EQ(r.componentCount, 1u);
}

TEST(Validate, ThreeFacesOnOneEdgeIsOneNonManifoldEdge)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(0, 0, 1), Vec3(1, 0, 0.5), Vec3(-0.5, 0.866, 0.5),
                Vec3(-0.5, -0.866, 0.5)};
  m.faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::NonManifoldEdge}) << r.toText();
  const MeshIssue& i = *r.issue(MeshIssueKind::NonManifoldEdge);
  EXPECT_EQ(i.count, 1u);
  EXPECT_EQ(i.elements, std::vector<int>{0});
  EXPECT_EQ(i.positions[0], Vec3(0, 0, 0.5));
  EXPECT_FALSE(r.isPlannable());
  // Six boundary edges meet three at a time at the spine's ends: one chain cannot close.
  size_t edges = 0;
  for (const BoundaryLoop& l : r.boundaryLoops) edges += l.vertices.size() - (l.closed ? 0 : 1);
  EXPECT_EQ(edges, 6u);
}

TEST(Validate, FinOnCylinderIsOneNonManifoldEdge)
{
  TriangleMesh m = cylinder();
  // The vertical edge v(2,0)-v(3,0) already has two faces; a fin adds a third.
  const int a = 2 * kSeg, b = 3 * kSeg;
  m.vertices.push_back(Vec3(2.0 * kR, 0.0, 12.5));
  m.faces.push_back({a, b, static_cast<int>(m.vertexCount() - 1)});
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::NonManifoldEdge}) << r.toText();
  EXPECT_EQ(r.issueCount(MeshIssueKind::NonManifoldEdge), 1u);
  EXPECT_EQ(r.issue(MeshIssueKind::NonManifoldEdge)->positions[0], Vec3(kR, 0.0, 12.5));
}

TEST(Validate, OneFlippedFaceIsOneFinding)
{
  TriangleMesh m = cylinder();
  const int f = quadFace(3, 7) + 1;
  std::swap(m.faces[f][1], m.faces[f][2]);
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::InconsistentOrientation}) << r.toText();
  const MeshIssue& i = *r.issue(MeshIssueKind::InconsistentOrientation);
  EXPECT_EQ(i.count, 1u);
  EXPECT_EQ(i.elements, std::vector<int>{f});
  EXPECT_TRUE(i.positions[0].isApprox(test::centroidOf(m, f), 1e-14));
  EXPECT_FALSE(r.isPlannable());
  EXPECT_EQ(r.boundaryLoops.size(), 2u);
  EXPECT_EQ(r.partClass, PartClass::Open);
}

TEST(Validate, FlippedFaceOnTheBaseStillGivesClosedLoops)
{
  TriangleMesh m = cylinder();
  const int f = quadFace(0, 0);  // its edge v(0,0)-v(0,1) is on the base loop
  std::swap(m.faces[f][1], m.faces[f][2]);
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.issueCount(MeshIssueKind::InconsistentOrientation), 1u);
  EXPECT_EQ(r.issue(MeshIssueKind::InconsistentOrientation)->elements, std::vector<int>{f});
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  for (const BoundaryLoop& l : r.boundaryLoops) {
    EXPECT_TRUE(l.closed);
    EXPECT_EQ(l.vertices.size(), static_cast<size_t>(kSeg));
    EXPECT_NEAR(l.length, polygonPerimeter(kSeg, kR), 1e-10);
  }
}

TEST(Validate, MajorityDecidesWhichFacesAreFlipped)
{
  TriangleMesh m = cylinder();
  for (Face& f : m.faces) std::swap(f[1], f[2]);  // all inward: consistent, so no finding
  EXPECT_FALSE(validateMesh(m).hasIssue(MeshIssueKind::InconsistentOrientation));
  std::swap(m.faces[0][1], m.faces[0][2]);  // face 0, the seed, is now the odd one out
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.issueCount(MeshIssueKind::InconsistentOrientation), 1u);
  EXPECT_EQ(r.issue(MeshIssueKind::InconsistentOrientation)->elements, std::vector<int>{0});
}

TEST(Validate, MoebiusStripIsNonOrientable)
{
  TriangleMesh m;
  const int n = 24;
  for (int j = 0; j < n; ++j) {
    const double t = 2.0 * kPi * j / n;
    const Vec3 c(10.0 * std::cos(t), 10.0 * std::sin(t), 0.0);
    const Vec3 radial(std::cos(t), std::sin(t), 0.0);
    const Vec3 w = std::cos(t / 2) * radial + std::sin(t / 2) * Vec3::UnitZ();
    m.vertices.push_back(c - 2.0 * w);
    m.vertices.push_back(c + 2.0 * w);
  }
  for (int j = 0; j < n; ++j) {
    const int a = 2 * j, b = 2 * j + 1;
    // The strip's half twist: after the last segment the two edges swap.
    const int c = j + 1 < n ? 2 * (j + 1) : 1, d = j + 1 < n ? 2 * (j + 1) + 1 : 0;
    m.faces.push_back({a, c, d});
    m.faces.push_back({a, d, b});
  }
  const MeshReport r = validateMesh(m);
  EXPECT_GE(r.issueCount(MeshIssueKind::InconsistentOrientation), 1u);
  EXPECT_FALSE(r.hasIssue(MeshIssueKind::NonManifoldEdge));
  EXPECT_FALSE(r.hasIssue(MeshIssueKind::NonManifoldVertex));
  ASSERT_EQ(r.boundaryLoops.size(), 1u);  // one edge that runs round twice
  EXPECT_TRUE(r.boundaryLoops[0].closed);
  EXPECT_EQ(r.boundaryLoops[0].vertices.size(), static_cast<size_t>(2 * n));
}

TEST(Validate, HoleInCylinderAddsALoopAndIsUnsupported)
{
  TriangleMesh m = cylinder();
  const int f = quadFace(3, 5);
  const Face removed = m.faces[f];
  m.faces.erase(m.faces.begin() + f);
  const MeshReport r = validateMesh(m);
  EXPECT_TRUE(r.issues.empty()) << r.toText();
  ASSERT_EQ(r.boundaryLoops.size(), 3u);
  const BoundaryLoop& hole = r.boundaryLoops[1];  // sorted by zMin: base, hole, rim
  ASSERT_EQ(hole.vertices.size(), 3u);
  EXPECT_TRUE(std::is_permutation(hole.vertices.begin(), hole.vertices.end(), removed.begin()));
  double perimeter = 0.0;
  for (int k = 0; k < 3; ++k) perimeter += (m.vertices[removed[k]] - m.vertices[removed[(k + 1) % 3]]).norm();
  EXPECT_NEAR(hole.length, perimeter, 1e-12);
  EXPECT_DOUBLE_EQ(hole.zMin, 15.0);
  EXPECT_DOUBLE_EQ(hole.zMax, 20.0);
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_EQ(r.classReason.rfind("3 boundary loops: the part has a hole or several branches", 0), 0u);
  EXPECT_TRUE(r.isPlannable());
}

TEST(Validate, HoleInHemisphereIsAnExtraLoop)
{
  TriangleMesh m = makeHemisphere(20.0, 32, 8);
  m.faces.erase(m.faces.begin() + 200);
  const MeshReport r = validateMesh(m);
  EXPECT_TRUE(r.issues.empty());
  ASSERT_EQ(r.boundaryLoops.size(), 2u);
  EXPECT_EQ(r.boundaryLoops[1].vertices.size(), 3u);
  EXPECT_GT(r.boundaryLoops[1].zMin, 0.0);
}

TEST(Validate, PlantedDuplicateAndDegenerateFacesAreFoundExactly)
{
  TriangleMesh m = cylinder();
  // A zero-area needle that closes a T-junction: split face (a, b, c) at the midpoint m of a-b
  // and fill the slit a-m-b with face (a, b, m). The topology stays clean.
  const int f = quadFace(2, 4);
  const Face abc = m.faces[f];
  const int mid = static_cast<int>(m.vertexCount());
  m.vertices.push_back(0.5 * (m.vertices[abc[0]] + m.vertices[abc[1]]));
  m.faces[f] = {abc[0], mid, abc[2]};
  m.faces.push_back({mid, abc[1], abc[2]});
  const int needle = static_cast<int>(m.faceCount());
  m.faces.push_back({abc[0], abc[1], mid});
  ASSERT_TRUE(validateMesh(m).isPlannable());
  // Copies of faces 5 and 9 (one reversed), and a face with a repeated index.
  const int first = static_cast<int>(m.faceCount());
  m.faces.push_back(m.faces[5]);
  m.faces.push_back({m.faces[9][0], m.faces[9][2], m.faces[9][1]});
  m.faces.push_back({m.faces[30][0], m.faces[30][0], m.faces[30][1]});

  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r),
            (std::set<MeshIssueKind>{MeshIssueKind::DegenerateFace, MeshIssueKind::DuplicateFace}))
      << r.toText();
  EXPECT_EQ(r.issue(MeshIssueKind::DuplicateFace)->elements, (std::vector<int>{first, first + 1}));
  EXPECT_EQ(r.issue(MeshIssueKind::DegenerateFace)->elements, (std::vector<int>{needle, first + 2}));
  EXPECT_EQ(r.issueCount(MeshIssueKind::DuplicateFace), 2u);
  EXPECT_EQ(r.issueCount(MeshIssueKind::DegenerateFace), 2u);
  EXPECT_EQ(r.boundaryLoops.size(), 2u);
  EXPECT_EQ(r.partClass, PartClass::Open);
  EXPECT_TRUE(r.isPlannable());
}

TEST(Validate, NonFiniteCoordinatesAreReportedWithoutCrashing)
{
  TriangleMesh m = cylinder();
  m.vertices[3 * kSeg + 2].x() = std::nan("");
  m.vertices[2 * kSeg + 9].z() = INFINITY;
  const MeshReport r = validateMesh(m);
  ASSERT_EQ(issueKinds(r), std::set<MeshIssueKind>{MeshIssueKind::NonFiniteCoordinate}) << r.toText();
  EXPECT_EQ(r.issue(MeshIssueKind::NonFiniteCoordinate)->elements,
            (std::vector<int>{2 * kSeg + 9, 3 * kSeg + 2}));
  EXPECT_FALSE(r.isPlannable());
  EXPECT_EQ(r.bounds.max, Vec3(kR, kR, kH));
  EXPECT_TRUE(std::isfinite(r.area));
  EXPECT_EQ(r.boundaryLoops.size(), 2u);
  const std::string json = r.toJson().dump();  // NaN positions become null
  EXPECT_NE(json.find("null"), std::string::npos);

  TriangleMesh base = cylinder();
  base.vertices[0].y() = std::nan("");  // on the base loop
  EXPECT_NO_THROW(validateMesh(base).toText());
}

TEST(Validate, ListsOnlyTheFirstFewElements)
{
  TriangleMesh m = cylinder();
  for (int v = 0; v < 25; ++v) m.vertices[kSeg + v].z() = std::nan("");
  const MeshReport r = validateMesh(m);
  const MeshIssue& i = *r.issue(MeshIssueKind::NonFiniteCoordinate);
  EXPECT_EQ(i.count, 25u);
  ASSERT_EQ(i.elements.size(), kMaxListedIssueElements);
  EXPECT_EQ(i.positions.size(), kMaxListedIssueElements);
  for (size_t k = 0; k < kMaxListedIssueElements; ++k) EXPECT_EQ(i.elements[k], kSeg + static_cast<int>(k));
}

TEST(Validate, SeparatePiecesAreCountedAndUnsupported)
{
  TriangleMesh b = cylinder();
  b.transform(transformFromXyzZyx(Vec3(100, 0, 0), 0, 0, 0));
  const MeshReport r = validateMesh(test::merged(cylinder(), b));
  EXPECT_TRUE(r.issues.empty());
  EXPECT_EQ(r.componentCount, 2u);
  EXPECT_EQ(r.boundaryLoops.size(), 4u);
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_EQ(r.classReason.rfind("2 separate pieces", 0), 0u);
}

TEST(Validate, EmptyMeshAndBadIndices)
{
  const MeshReport r = validateMesh(TriangleMesh());
  EXPECT_EQ(r.componentCount, 0u);
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_FALSE(r.classReason.empty());
  TriangleMesh bad = makeTetrahedron(1.0);
  bad.faces[2][1] = 4;
  EXPECT_THROW(validateMesh(bad), InputError);
  bad.faces[2][1] = -1;
  EXPECT_THROW(validateMesh(bad), InputError);
}

TEST(Validate, TextAndJsonCarryTheFindings)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, -0.5, 0), Vec3(1, 0.5, 0), Vec3(-1, 0.5, 0), Vec3(-1, -0.5, 0)};
  m.faces = {{0, 1, 2}, {0, 3, 4}};
  const MeshReport r = validateMesh(m);
  const std::string text = r.toText();
  EXPECT_NE(text.find("Mesh: 5 vertices, 2 faces, 6 edges"), std::string::npos) << text;
  EXPECT_NE(text.find("Issue: 1 non-manifold vertex (faces touch only at the vertex)"), std::string::npos)
      << text;
  EXPECT_NE(text.find("vertex 0 at (0, 0, 0) mm"), std::string::npos) << text;
  EXPECT_NE(text.find("Boundary loops: 2"), std::string::npos) << text;
  EXPECT_NE(text.find("Connected components: 1"), std::string::npos) << text;
  EXPECT_NE(text.find("x -1 .. 1, y -0.5 .. 0.5, z 0 .. 0 mm"), std::string::npos) << text;
  EXPECT_NE(text.find("Surface area: 1 mm^2"), std::string::npos) << text;

  const nlohmann::json j = r.toJson();
  EXPECT_EQ(j["part_class"], "open");
  EXPECT_EQ(j["plannable"], false);
  ASSERT_EQ(j["issues"].size(), 1u);
  EXPECT_EQ(j["issues"][0]["kind"], "non_manifold_vertex");
  EXPECT_EQ(j["issues"][0]["count"], 1);
  EXPECT_EQ(j["issues"][0]["elements"][0], 0);
  EXPECT_EQ(j["boundary_loops"].size(), 2u);
  EXPECT_EQ(j["bounds_mm"]["max"][0], 1.0);
  EXPECT_DOUBLE_EQ(j["area_mm2"].get<double>(), 1.0);

  const std::string clean = validateMesh(cylinder()).toText();
  EXPECT_NE(clean.find("Issues: none"), std::string::npos);
  EXPECT_NE(clean.find("Part class: open - 2 boundary loops"), std::string::npos);
}

TEST(Validate, ASingleTriangleIsNoWall)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 0, 10)};
  m.faces = {{0, 1, 2}};
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.boundaryLoops.size(), 1u);
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_NE(r.classReason.find("every vertex lies on the part's one boundary edge"), std::string::npos)
      << r.classReason;
}

TEST(Validate, AMeshCollapsedToALineHasNoSurface)
{
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(20, 0, 0), Vec3(30, 0, 0)};
  m.faces = {{0, 1, 2}, {0, 2, 3}};
  const MeshReport r = validateMesh(m);
  EXPECT_EQ(r.issueCount(MeshIssueKind::DegenerateFace), 2u);
  EXPECT_FALSE(r.isPlannable());
  EXPECT_EQ(r.partClass, PartClass::Unsupported);
  EXPECT_NE(r.classReason.find("all 2 faces are degenerate"), std::string::npos) << r.classReason;
}
