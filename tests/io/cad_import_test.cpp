// CAD import checked against analytic shapes made here with OpenCASCADE. This file includes
// OpenCASCADE and must never include CGAL (OpenCASCADE's Handle macro breaks it).
#include <gtest/gtest.h>

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakeRevol.hxx>
#include <BRepTools.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <TopLoc_Location.hxx>
#include <TopoDS_Edge.hxx>
#include <TopoDS_Shape.hxx>
#include <gp_Ax1.hxx>
#include <gp_Trsf.hxx>

#include <cmath>
#include <filesystem>

#include "io_test_util.h"
#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/planning/planner.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

// The wall of a cone (or cylinder when r0 == r1) about +Z from z = 0 to z = height: the thin-wall
// parts Spira plans are shells like this one.
TopoDS_Shape revolvedWall(double r0, double r1, double height)
{
  const TopoDS_Edge profile = BRepBuilderAPI_MakeEdge(gp_Pnt(r0, 0, 0), gp_Pnt(r1, 0, height));
  return BRepPrimAPI_MakeRevol(profile, gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 2 * M_PI).Shape();
}

TopoDS_Shape scaled(const TopoDS_Shape& shape, double factor)
{
  gp_Trsf T;
  T.SetScale(gp_Pnt(0, 0, 0), factor);
  return BRepBuilderAPI_Transform(shape, T, true).Shape();
}

// OpenCASCADE 7.6 writes coordinates as they are and only labels them with `unit`.
void writeStep(const TopoDS_Shape& shape, const fs::path& file, const char* unit = "MM")
{
  STEPControl_Writer writer;
  Interface_Static::SetCVal("write.step.unit", unit);
  ASSERT_EQ(writer.Transfer(shape, STEPControl_AsIs), IFSelect_RetDone);
  Interface_Static::SetCVal("write.step.unit", "MM");
  ASSERT_EQ(writer.Write(file.c_str()), IFSelect_RetDone);
}

void writeIges(const TopoDS_Shape& shape, const fs::path& file, const char* unit = "MM")
{
  IGESControl_Controller::Init();
  IGESControl_Writer writer(unit, 1);  // mode 1: BRep entities, so faces keep their shells
  ASSERT_TRUE(writer.AddShape(shape));
  writer.ComputeModel();
  ASSERT_TRUE(writer.Write(file.c_str()));
}

void writeBrep(const TopoDS_Shape& shape, const fs::path& file)
{
  ASSERT_TRUE(BRepTools::Write(shape, file.c_str()));
}

ImportedPart importWithDeflection(const fs::path& file, double linear)
{
  return importFile(file, "linear_deflection", linear);
}

constexpr double kOnSurface = 1e-6;  // mm: vertices are evaluated on the exact surface

TEST(CadImport, StepCylinderWallHonoursTheDeflection)
{
  const double R = 50.0, H = 80.0;
  TempDir dir;
  writeStep(revolvedWall(R, R, H), dir / "wall.step");
  double previousError = 1e9;
  size_t previousFaces = 0;
  for (double deflection : {0.1, 0.02}) {
    const ImportedPart part = importWithDeflection(dir / "wall.step", deflection);
    EXPECT_EQ(part.importerId, "import.step");
    EXPECT_EQ(part.sourceUnit, LengthUnit::Millimetre);
    EXPECT_LT(maxDistanceToRevolvedLine(part.mesh, R, R, H, true), kOnSurface);
    const double chord = maxDistanceToRevolvedLine(part.mesh, R, R, H, false);
    EXPECT_LE(chord, deflection) << "deflection " << deflection;
    EXPECT_GT(chord, 0.25 * deflection) << "the mesh is far finer than asked: the deflection was not used";
    EXPECT_GT(part.mesh.faceCount(), previousFaces);
    EXPECT_LT(chord, previousError);
    previousError = chord;
    previousFaces = part.mesh.faceCount();
    EXPECT_NEAR(part.mesh.bounds().min.z(), 0.0, kOnSurface);
    EXPECT_NEAR(part.mesh.bounds().max.z(), H, kOnSurface);
    EXPECT_EQ(part.report.partClass, PartClass::Open) << part.report.classReason;
    EXPECT_EQ(part.report.boundaryLoops.size(), 2u);
    EXPECT_TRUE(part.report.isPlannable());
  }
}

TEST(CadImport, StepConeWallHonoursTheDeflection)
{
  const double r0 = 60.0, r1 = 35.0, H = 50.0;
  TempDir dir;
  writeStep(revolvedWall(r0, r1, H), dir / "cone.stp");
  for (double deflection : {0.2, 0.05}) {
    const ImportedPart part = importWithDeflection(dir / "cone.stp", deflection);
    EXPECT_LT(maxDistanceToRevolvedLine(part.mesh, r0, r1, H, true), kOnSurface);
    EXPECT_LE(maxDistanceToRevolvedLine(part.mesh, r0, r1, H, false), deflection);
    EXPECT_EQ(part.report.partClass, PartClass::Open);
  }
}

TEST(CadImport, StepWrittenInMetresComesInMillimetres)
{
  const double R = 50.0, H = 80.0;  // mm; the file holds 0.05 and 0.08 metres
  TempDir dir;
  writeStep(scaled(revolvedWall(R, R, H), 1e-3), dir / "metres.step", "M");
  const std::string text = readFile(dir / "metres.step");
  EXPECT_NE(text.find("SI_UNIT($,.METRE.)"), std::string::npos) << "the fixture is not in metres";
  EXPECT_EQ(text.find(".MILLI."), std::string::npos) << "the fixture is not in metres";
  EXPECT_NE(text.find("CARTESIAN_POINT('',(5.E-02,0.,8.E-02))"), std::string::npos)
      << "no top corner in metres";

  const double deflection = 0.05;
  const ImportedPart part = importWithDeflection(dir / "metres.step", deflection);
  EXPECT_EQ(part.sourceUnit, LengthUnit::Metre);
  EXPECT_NEAR(part.mesh.bounds().max.z(), H, kOnSurface);
  EXPECT_NEAR(part.mesh.bounds().size().x(), 2 * R, 2 * deflection);
  EXPECT_LT(maxDistanceToRevolvedLine(part.mesh, R, R, H, true), kOnSurface);
  EXPECT_LE(maxDistanceToRevolvedLine(part.mesh, R, R, H, false), deflection);
}

TEST(CadImport, IgesInMillimetresAndInches)
{
  const double R = 40.0, H = 30.0;
  TempDir dir;
  writeIges(revolvedWall(R, R, H), dir / "wall.igs", "MM");
  writeIges(revolvedWall(R, R, H), dir / "wall_in.iges", "IN");
  for (const auto& [name, unit] :
       {std::pair{"wall.igs", LengthUnit::Millimetre}, std::pair{"wall_in.iges", LengthUnit::Inch}}) {
    const ImportedPart part = importWithDeflection(dir / name, 0.05);
    EXPECT_EQ(part.importerId, "import.iges");
    EXPECT_EQ(part.sourceUnit, unit) << name;
    EXPECT_NEAR(part.mesh.bounds().max.z(), H, 1e-5) << name;
    EXPECT_LT(maxDistanceToRevolvedLine(part.mesh, R, R, H, true), 1e-5) << name;
    EXPECT_LE(maxDistanceToRevolvedLine(part.mesh, R, R, H, false), 0.05) << name;
    EXPECT_EQ(part.report.partClass, PartClass::Open) << name;
  }
}

TEST(CadImport, BrepUsesItsUnitParameterForCoordinatesAndDeflection)
{
  const double R = 0.05, H = 0.03;  // written as metres
  TempDir dir;
  writeBrep(revolvedWall(R, R, H), dir / "wall.brep");
  ParamSet params;
  params.set("unit", std::string("m"));
  params.set("linear_deflection", 0.1);
  NullProgress progress;
  const ImportedPart part = importPart(ioRegistry(), dir / "wall.brep", &params, progress);
  EXPECT_EQ(part.importerId, "import.brep");
  EXPECT_EQ(part.sourceUnit, LengthUnit::Metre);
  EXPECT_NEAR(part.mesh.bounds().max.z(), 30.0, kOnSurface);
  EXPECT_LT(maxDistanceToRevolvedLine(part.mesh, 50.0, 50.0, 30.0, true), kOnSurface);
  const double chord = maxDistanceToRevolvedLine(part.mesh, 50.0, 50.0, 30.0, false);
  EXPECT_LE(chord, 0.1);
  EXPECT_GT(chord, 0.025);  // the deflection was converted to metres, not applied as 0.1 m
}

TEST(CadImport, SolidsComeOutWatertightAndFacingOutwards)
{
  TempDir dir;
  writeStep(BRepPrimAPI_MakeBox(20.0, 30.0, 40.0).Shape(), dir / "box.step");
  const ImportedPart box = importFile(dir / "box.step");
  EXPECT_TRUE(box.report.boundaryLoops.empty()) << box.report.classReason;
  EXPECT_EQ(box.report.componentCount, 1u);
  EXPECT_FALSE(box.report.hasIssue(MeshIssueKind::InconsistentOrientation));
  EXPECT_NEAR(signedVolume(box.mesh), 20.0 * 30.0 * 40.0, 1e-6);

  const double R = 25.0, H = 60.0, deflection = 0.05;
  writeIges(BRepPrimAPI_MakeCylinder(R, H).Shape(), dir / "cyl.igs");
  const ImportedPart cyl = importWithDeflection(dir / "cyl.igs", deflection);
  EXPECT_TRUE(cyl.report.boundaryLoops.empty()) << cyl.report.classReason;
  EXPECT_EQ(cyl.report.componentCount, 1u);
  EXPECT_FALSE(cyl.report.hasIssue(MeshIssueKind::InconsistentOrientation));
  const double exact = M_PI * R * R * H;
  // Inscribed facets lose at most (lateral area) * deflection of volume.
  EXPECT_LT(signedVolume(cyl.mesh), exact);
  EXPECT_GT(signedVolume(cyl.mesh), exact - 2 * M_PI * R * H * deflection);
}

// A thin-walled tube as CAD models it (a cylinder minus its bore, one solid) takes the road of an
// STL solid: its wall measured, and planned on its mid-surface.
TEST(CadImport, StepThinWalledTubeSolidIsPlannedOnItsMidSurface)
{
  TempDir dir;
  const double R = 30.0, r = 27.0, H = 50.0, deflection = 0.01;
  BRepAlgoAPI_Cut tube(BRepPrimAPI_MakeCylinder(R, H).Shape(), BRepPrimAPI_MakeCylinder(r, H).Shape());
  ASSERT_TRUE(tube.IsDone());
  writeStep(tube.Shape(), dir / "tube.step");
  const ImportedPart part = importWithDeflection(dir / "tube.step", deflection);
  ASSERT_TRUE(isClosedSolid(part.report)) << part.report.toText();
  PlanRequest request(part.mesh, part.report);
  NullProgress progress;
  const PlanOutput plan = planPart(ioRegistry(), request, progress);
  ASSERT_TRUE(plan.solid);
  // Both skins are inscribed polygons within the deflection of their circles.
  EXPECT_NEAR(plan.solid->thickness.median, R - r, 2 * deflection);
  const TriangleMesh& mid = *plan.solid->midSurface;
  EXPECT_EQ(validateMesh(mid).boundaryLoops.size(), 2u);
  for (const Vec3& v : mid.vertices) EXPECT_NEAR(std::hypot(v.x(), v.y()), 0.5 * (R + r), 2 * deflection);
  EXPECT_EQ(plan.topology.partClass, PartClass::Open);
  EXPECT_NEAR(plan.topology.upper->zMin, H, 1e-6);
}

TEST(CadImport, LocationsArePlacedAndKeepOrientation)
{
  gp_Trsf T;
  T.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), M_PI / 2);
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(100.0, 0.0, 5.0));
  const TopoDS_Shape placed = BRepPrimAPI_MakeBox(20.0, 30.0, 40.0).Shape().Moved(TopLoc_Location(shift * T));
  TempDir dir;
  writeBrep(placed, dir / "placed.brep");
  const ImportedPart part = importFile(dir / "placed.brep");
  // Rotated by 90 degrees about Z, x spans [-30, 0] and y [0, 20]; then shifted.
  EXPECT_NEAR(part.mesh.bounds().min.x(), 70.0, 1e-9);
  EXPECT_NEAR(part.mesh.bounds().max.x(), 100.0, 1e-9);
  EXPECT_NEAR(part.mesh.bounds().min.y(), 0.0, 1e-9);
  EXPECT_NEAR(part.mesh.bounds().max.y(), 20.0, 1e-9);
  EXPECT_NEAR(part.mesh.bounds().min.z(), 5.0, 1e-9);
  EXPECT_NEAR(signedVolume(part.mesh), 24000.0, 1e-6);
}

TEST(CadImport, SchemasAreSoundAndBoundsEnforced)
{
  for (const char* id : {"import.step", "import.iges", "import.brep"}) {
    const ImporterPlugin& importer = ioRegistry().importer(id);
    EXPECT_TRUE(importer.schema().selfCheck().empty()) << id;
    const ParamDef* lin = importer.schema().find("linear_deflection");
    ASSERT_NE(lin, nullptr);
    EXPECT_EQ(lin->unit, "mm");
    EXPECT_EQ(std::get<double>(lin->defaultValue), 0.1);
    const ParamDef* ang = importer.schema().find("angular_deflection");
    ASSERT_NE(ang, nullptr);
    EXPECT_EQ(ang->unit, "deg");
  }
  EXPECT_NE(ioRegistry().importer("import.brep").schema().find("unit"), nullptr);
  EXPECT_EQ(ioRegistry().importer("import.step").schema().find("unit"), nullptr);
  TempDir dir;
  writeStep(revolvedWall(10.0, 10.0, 10.0), dir / "w.step");
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importWithDeflection(dir / "w.step", 0.0); }, "out of range"));
}

TEST(CadImport, CancelStopsTheImport)
{
  TempDir dir;
  writeStep(revolvedWall(50.0, 50.0, 50.0), dir / "w.step");
  CallbackProgress progress;
  progress.cancel();
  EXPECT_THROW(importPart(ioRegistry(), dir / "w.step", nullptr, progress), Cancelled);
}

}  // namespace
}  // namespace spira::test
