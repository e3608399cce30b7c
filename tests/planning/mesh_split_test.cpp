#include <gtest/gtest.h>

#include <cmath>

#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/contour/mesh_split.h"
#include "spira/mesh/mesh_primitives.h"
#include "spira/mesh/mesh_report.h"

namespace spira {
namespace {

std::vector<double> heights(const TriangleMesh& m)
{
  std::vector<double> z(m.vertexCount());
  for (size_t v = 0; v < z.size(); ++v) z[v] = m.vertices[v].z();
  return z;
}

TriangleMesh side(const LevelCut& cut, bool above)
{
  std::vector<int> faces;
  for (size_t f = 0; f < cut.above.size(); ++f)
    if ((cut.above[f] != 0) == above) faces.push_back(static_cast<int>(f));
  return extractFaces(cut.mesh, faces).mesh;
}

// A prism tube: its lateral area is the polygon's perimeter times the height, exactly, so both
// sides of a horizontal cut have known areas.
TEST(MeshSplit, CutAcrossATubeGivesTwoManifoldTubesWithTheExactAreas)
{
  const int n = 48;
  const double r = 20.0, h = 60.0;
  const TriangleMesh tube = makeOpenCylinder(r, h, n, 17);  // ring spacing 60/17: 37.3 falls inside
  const double perimeter = 2.0 * n * r * std::sin(kPi / n);
  const double level = 37.3;
  const LevelCut cut = cutAlongLevel(tube, heights(tube), level);
  EXPECT_EQ(cut.newVertexCount(), static_cast<size_t>(2 * n));  // one per vertical and diagonal edge
  for (size_t v = tube.vertexCount(); v < cut.mesh.vertexCount(); ++v) {
    EXPECT_NEAR(cut.mesh.vertices[v].z(), level, 1e-12);
    EXPECT_NE(cut.origin[v].v0, cut.origin[v].v1);
    EXPECT_GT(cut.origin[v].t, 0.05);
    EXPECT_LT(cut.origin[v].t, 0.95);
  }
  for (size_t f = 0; f < cut.mesh.faceCount(); ++f) {
    const Face& fc = cut.mesh.faces[f];
    for (int k = 0; k < 3; ++k) {
      const double z = cut.mesh.vertices[fc[k]].z();
      if (cut.above[f])
        EXPECT_GE(z, level - 1e-12);
      else
        EXPECT_LE(z, level + 1e-12);
    }
    // Orientation kept: the refined face's normal agrees with its parent's.
    EXPECT_GT(cut.mesh.faceNormal(f).dot(tube.faceNormal(static_cast<size_t>(cut.parentFace[f]))), 0.999);
  }
  const TriangleMesh below = side(cut, false), above = side(cut, true);
  for (const TriangleMesh* m : {&below, &above}) {
    const MeshReport rep = validateMesh(*m);
    EXPECT_TRUE(rep.isPlannable()) << rep.toText();
    EXPECT_EQ(rep.componentCount, 1u);
    ASSERT_EQ(rep.boundaryLoops.size(), 2u);
    EXPECT_EQ(rep.issueCount(MeshIssueKind::DegenerateFace), 0u);
  }
  EXPECT_NEAR(validateMesh(below).area, perimeter * level, 1e-9 * perimeter * h);
  EXPECT_NEAR(validateMesh(above).area, perimeter * (h - level), 1e-9 * perimeter * h);
  // The cut loop is the polygon at z = 37.3 on both sides.
  const MeshReport b = validateMesh(below);
  EXPECT_NEAR(b.boundaryLoops[1].zMin, level, 1e-12);
  EXPECT_NEAR(b.boundaryLoops[1].length, perimeter, 1e-9);
}

TEST(MeshSplit, ALevelThroughARingOfVerticesCutsThroughThem)
{
  const TriangleMesh tube = makeOpenCylinder(10.0, 30.0, 24, 6);  // rings every 5 mm
  const LevelCut cut = cutAlongLevel(tube, heights(tube), 15.0);
  EXPECT_EQ(cut.newVertexCount(), 0u);
  EXPECT_EQ(cut.mesh.faceCount(), tube.faceCount());
  // A level within 5 % of an edge's rise from a ring snaps onto it; one just outside does not.
  const double rise = 5.0;
  EXPECT_EQ(cutAlongLevel(tube, heights(tube), 15.0 + 0.04 * rise).newVertexCount(), 0u);
  EXPECT_EQ(cutAlongLevel(tube, heights(tube), 15.0 + 0.06 * rise).newVertexCount(), 48u);
  const LevelCut halves = cutAlongLevel(tube, heights(tube), 15.0);
  EXPECT_NEAR(validateMesh(side(halves, false)).area, validateMesh(side(halves, true)).area, 1e-9);
}

TEST(MeshSplit, CarriedValuesInterpolateAlongTheCutEdges)
{
  const TriangleMesh tube = makeOpenCylinder(10.0, 30.0, 24, 6);
  const std::vector<double> z = heights(tube);
  const LevelCut cut = cutAlongLevel(tube, z, 12.34);
  // Any affine function of position is carried exactly: x + 2y - z.
  std::vector<double> f(tube.vertexCount());
  for (size_t v = 0; v < f.size(); ++v)
    f[v] = tube.vertices[v].x() + 2.0 * tube.vertices[v].y() - tube.vertices[v].z();
  const std::vector<double> g = carryToCut(cut, f);
  ASSERT_EQ(g.size(), cut.mesh.vertexCount());
  for (size_t v = 0; v < g.size(); ++v) {
    const Vec3& p = cut.mesh.vertices[v];
    EXPECT_NEAR(g[v], p.x() + 2.0 * p.y() - p.z(), 1e-12);
  }
}

TEST(MeshSplit, AMaskLeavesTheOtherFacesWhole)
{
  const TriangleMesh tube = makeOpenCylinder(10.0, 30.0, 24, 6);
  std::vector<std::uint8_t> mask(tube.faceCount(), 0);
  for (size_t f = 0; f < tube.faceCount(); f += 2) mask[f] = 1;
  const LevelCut cut = cutAlongLevel(tube, heights(tube), 12.34, &mask);
  size_t kept = 0;
  for (size_t f = 0; f < cut.mesh.faceCount(); ++f)
    if (!mask[static_cast<size_t>(cut.parentFace[f])]) {
      EXPECT_EQ(cut.mesh.faces[f], tube.faces[static_cast<size_t>(cut.parentFace[f])]);
      EXPECT_EQ(cut.above[f], 0);
      ++kept;
    }
  EXPECT_EQ(kept, tube.faceCount() / 2);
}

TEST(MeshSplit, ComponentsAreJoinedByEdgesNotByVertices)
{
  // Two triangles sharing only vertex 0, and a third sharing an edge with the second.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {-1, -1, 0}};
  m.faces = {{0, 1, 2}, {0, 3, 4}, {3, 5, 4}};
  std::vector<int> component;
  EXPECT_EQ(faceComponents(m, std::vector<std::uint8_t>(3, 1), component), 2);
  EXPECT_EQ(component, (std::vector<int>{0, 1, 1}));
  EXPECT_EQ(faceComponents(m, std::vector<std::uint8_t>{1, 0, 1}, component), 2);
  EXPECT_EQ(component, (std::vector<int>{0, -1, 1}));
  const SubMesh sub = extractFaces(m, {2, 1});
  EXPECT_EQ(sub.mesh.vertexCount(), 4u);
  EXPECT_EQ(sub.parentVertex, (std::vector<int>{3, 5, 4, 0}));
  EXPECT_EQ(sub.mesh.faces[0], (Face{0, 1, 2}));
  EXPECT_EQ(sub.mesh.faces[1], (Face{3, 0, 2}));
}

TEST(MeshSplit, RefusesAFieldOfTheWrongSize)
{
  const TriangleMesh tube = makeOpenCylinder(10.0, 30.0, 24, 6);
  EXPECT_THROW(cutAlongLevel(tube, std::vector<double>(3, 0.0), 1.0), InputError);
}

}  // namespace
}  // namespace spira
