// Bad input of every kind must end in InputError or IoError with a one-line message and a hint,
// never a crash; defects that do not stop an import must be imported and reported.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>

#include "io_test_util.h"
#include "spira/base/error.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"
#include "support/test_support.h"

namespace spira::test {
namespace {

std::string randomBytes(size_t n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::string s(n, '\0');
  for (char& c : s) c = static_cast<char>(rng() & 0xFF);
  return s;
}

TEST(ImportErrors, MissingFileIsIoError)
{
  TempDir dir;
  EXPECT_TRUE(throwsOneLine<IoError>([&] { importFile(dir / "nowhere.stl"); }, "does not exist"));
}

TEST(ImportErrors, DirectoryIsIoError)
{
  TempDir dir;
  std::filesystem::create_directory(dir / "folder.stl");
  EXPECT_TRUE(throwsOneLine<IoError>([&] { importFile(dir / "folder.stl"); }, "is a folder"));
}

TEST(ImportErrors, UnsupportedExtensionListsTheSupportedOnes)
{
  TempDir dir;
  writeBytes(dir / "part.3mf", "PK\x03\x04");
  EXPECT_TRUE(
      throwsOneLine<InputError>([&] { importFile(dir / "part.3mf"); }, "unsupported file type '.3mf'"));
  try {
    importFile(dir / "part.3mf");
  } catch (const InputError& e) {
    for (const char* ext : {".stl", ".obj", ".ply", ".step", ".stp", ".iges", ".igs", ".brep"})
      EXPECT_NE(e.hint().find(ext), std::string::npos) << ext;
  }
}

TEST(ImportErrors, EmptyFileOfEveryFormat)
{
  TempDir dir;
  for (const char* name : {"e.stl", "e.obj", "e.ply", "e.step", "e.iges", "e.brep"}) {
    writeBytes(dir / name, "");
    EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / name); }, "is empty")) << name;
  }
}

TEST(ImportErrors, BinaryStlWithWrongTriangleCount)
{
  TempDir dir;
  std::string bytes = encodeMesh(makeTetrahedron(4.0), MeshFileFormat::StlBinary);
  bytes += std::string(50, '\0');  // one facet more than the header announces
  writeBytes(dir / "extra.stl", bytes);
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / "extra.stl"); },
                                        "take 284 bytes, but the file has 334 bytes"));
}

TEST(ImportErrors, NanCoordinateGivesCountAndFirstPosition)
{
  TempDir dir;
  writeBytes(dir / "nan.stl",
             "solid s\n"
             "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 nan 0\nvertex 0 1 0\nendloop\nendfacet\n"
             "facet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 2 0 0\nvertex inf 1 0\nendloop\nendfacet\n"
             "endsolid s\n");
  EXPECT_TRUE(
      throwsOneLine<InputError>([&] { importFile(dir / "nan.stl"); },
                                "2 vertices have non-finite coordinates (NaN or infinity); the first is "
                                "corner 1 of triangle 1 at (1, nan, 0)"));
}

TEST(ImportErrors, ObjWithoutTrianglesIsRefused)
{
  TempDir dir;
  writeBytes(dir / "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2\n");
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / "points.obj"); }));
}

TEST(ImportErrors, GarbageBytesWithEveryExtension)
{
  TempDir dir;
  unsigned seed = 1;
  for (const char* name : {"g.stl", "g.obj", "g.ply", "g.step", "g.stp", "g.iges", "g.igs", "g.brep"}) {
    for (size_t size : {size_t{17}, size_t{5000}}) {
      writeBytes(dir / name, randomBytes(size, seed++));
      bool refused = false;
      try {
        importFile(dir / name);
      } catch (const InputError& e) {
        refused = std::string(e.what()).find('\n') == std::string::npos && !e.hint().empty();
      } catch (const IoError& e) {
        refused = std::string(e.what()).find('\n') == std::string::npos && !e.hint().empty();
      }
      EXPECT_TRUE(refused) << name << " (" << size << " bytes)";
    }
  }
}

TEST(ImportErrors, TextThatIsNoFormat)
{
  TempDir dir;
  const std::string text = "this is a note, not a part\nsecond line\n";
  for (const char* name : {"t.stl", "t.ply", "t.step", "t.iges", "t.brep"}) {
    writeBytes(dir / name, text);
    bool refused = false;
    try {
      importFile(dir / name);
    } catch (const InputError&) {
      refused = true;
    }
    EXPECT_TRUE(refused) << name;
  }
}

TEST(ImportErrors, InvalidParameterValuesAreRefused)
{
  TempDir dir;
  writeMesh(makeTetrahedron(3.0), dir / "t.stl");
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / "t.stl", "unit", std::string("furlong")); },
                                        "not an allowed choice"));
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / "t.stl", "deflection", 0.1); },
                                        "unknown parameter 'deflection'"));
}

TEST(ImportReports, ZeroAreaFacesAreImportedAndReported)
{
  // A strip of two triangles plus a sliver whose corners are collinear.
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {10, 0, 0}, {10, 10, 0}, {0, 10, 0}, {5, 0, 0}};
  m.faces = {{0, 1, 2}, {0, 2, 3}, {0, 4, 1}};
  TempDir dir;
  writeMesh(m, dir / "sliver.stl", MeshFileFormat::StlAscii);
  const ImportedPart part = importFile(dir / "sliver.stl");
  EXPECT_EQ(part.mesh.faceCount(), 3u);
  EXPECT_EQ(part.mesh.vertexCount(), 5u);
  ASSERT_EQ(part.report.issueCount(MeshIssueKind::DegenerateFace), 1u);
  for (const MeshIssue& issue : part.report.issues)
    if (issue.kind == MeshIssueKind::DegenerateFace) {
      ASSERT_EQ(issue.elements.size(), 1u);
      EXPECT_EQ(issue.elements[0], 2);
      ASSERT_EQ(issue.positions.size(), 1u);
      EXPECT_NEAR(issue.positions[0].x(), 5.0, 5.0);
      EXPECT_NEAR(issue.positions[0].y(), 0.0, 1e-9);
    }
}

TEST(ImportReports, NonManifoldEdgeIsImportedAndReported)
{
  // Three fins sharing the edge (0,0,0)-(0,0,10).
  TriangleMesh m;
  m.vertices = {{0, 0, 0}, {0, 0, 10}, {10, 0, 5}, {-5, 8, 5}, {-5, -8, 5}};
  m.faces = {{0, 2, 1}, {0, 3, 1}, {0, 4, 1}};
  TempDir dir;
  writeMesh(m, dir / "fins.obj", MeshFileFormat::Obj);
  const ImportedPart part = importFile(dir / "fins.obj");
  EXPECT_EQ(part.mesh.faceCount(), 3u);
  EXPECT_EQ(part.mesh.vertexCount(), 5u);
  EXPECT_EQ(part.report.issueCount(MeshIssueKind::NonManifoldEdge), 1u);
  EXPECT_FALSE(part.report.isPlannable());
}

TEST(ImportProgress, CancelIsHonouredAndStagesAreReported)
{
  TempDir dir;
  writeMesh(makeOpenCylinder(20.0, 30.0, 32, 8), dir / "c.ply");
  std::vector<std::string> stages;
  CallbackProgress progress([&](double, std::string_view stage) { stages.emplace_back(stage); });
  const ImportedPart part = importPart(ioRegistry(), dir / "c.ply", nullptr, progress);
  EXPECT_EQ(part.mesh.faceCount(), 2u * 32u * 8u);
  EXPECT_NE(std::find(stages.begin(), stages.end(), "Welding"), stages.end());
  EXPECT_NE(std::find(stages.begin(), stages.end(), "Validating"), stages.end());
  CallbackProgress cancelled;
  cancelled.cancel();
  EXPECT_THROW(importPart(ioRegistry(), dir / "c.ply", nullptr, cancelled), Cancelled);
}

}  // namespace
}  // namespace spira::test
