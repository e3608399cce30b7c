// Damaged STEP files (tests/data/hostile/step, each one edit away from a box OpenCASCADE wrote)
// and the limits of the import helper: every one must come back as an InputError naming the
// file, never as a crash of the calling process or a part with faces silently missing. This file
// includes OpenCASCADE and must never include CGAL.
#include <gtest/gtest.h>

#include <BRepPrimAPI_MakeBox.hxx>
#include <BRep_Builder.hxx>
#include <STEPControl_Writer.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cstdlib>
#include <regex>

#include "io_test_util.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path hostile(const std::string& name)
{
  return sourceDir() / "tests/data/hostile/step" / name;
}

// Sets an environment variable for one test.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
};

// `count` disjoint 10 x 20 x 30 boxes in one STEP file: 6 * count faces.
void writeBoxes(int count, const fs::path& file)
{
  BRep_Builder builder;
  TopoDS_Compound boxes;
  builder.MakeCompound(boxes);
  for (int i = 0; i < count; ++i)
    builder.Add(boxes, BRepPrimAPI_MakeBox(gp_Pnt(40.0 * i, 0, 0), 10, 20, 30).Shape());
  STEPControl_Writer writer;
  ASSERT_EQ(writer.Transfer(boxes, STEPControl_AsIs), IFSelect_RetDone);
  ASSERT_EQ(writer.Write(file.c_str()), IFSelect_RetDone);
}

TEST(HostileStep, WrongTypedReferenceThatCrashesOpenCascadeIsAnInputError)
{
  // LINE('',#28,#30): #30 is a DIRECTION where a VECTOR is expected; OpenCASCADE 7.6 dies on it
  // with SIGSEGV inside the transfer.
  EXPECT_TRUE(throwsOneLine<InputError>([] { importFile(hostile("wrong_type_crash.step")); },
                                        "the STEP reader crashed on 'wrong_type_crash.step' (signal 11"));
}

TEST(HostileStep, FacesLostToBadReferencesAreRefused)
{
  // Each file declares the box's 6 faces; one of them does not survive the transfer.
  for (const char* name : {"missing_reference.step", "wrong_type_reference.step", "unresolved_face.step"})
    EXPECT_TRUE(
        throwsOneLine<InputError>([&] { importFile(hostile(name)); },
                                  "'" + std::string(name) + "' declares 6 faces but only 5 could be read"))
        << name;
}

TEST(HostileStep, UnresolvedReferenceOutsideTheShapeIsAWarning)
{
  // #12 (the placement of the representation) points to #999: the box is whole, OpenCASCADE's
  // complaint comes back as a warning.
  const ImportedPart part = importFile(hostile("unresolved_point.step"));
  EXPECT_EQ(part.mesh.faces.size(), 12u);
  EXPECT_NEAR(part.report.area, 2200.0, 1e-9);
  ASSERT_EQ(part.warnings.size(), 1u);
  EXPECT_NE(part.warnings[0].find("Unresolved Reference"), std::string::npos) << part.warnings[0];
  EXPECT_EQ(part.warnings[0].find('\x1b'), std::string::npos) << "terminal escapes: " << part.warnings[0];
}

TEST(HostileStep, FewFacesLostIsAWarningThatCountsThem)
{
  TempDir dir;
  writeBoxes(25, dir / "boxes.step");
  std::string text = readBytes(dir / "boxes.step");
  // The first shell loses its first face: 149 of the 150 faces remain.
  const std::regex firstFace(R"((CLOSED_SHELL\('',\()#\d+)");
  text = std::regex_replace(text, firstFace, "$1#999999", std::regex_constants::format_first_only);
  writeBytes(dir / "boxes.step", text);
  const ImportedPart part = importFile(dir / "boxes.step");
  EXPECT_EQ(part.mesh.faces.size(), 149u * 2);
  bool counted = false;
  for (const std::string& w : part.warnings)
    counted = counted || w.find("declares 150 faces but only 149 could be read") != std::string::npos;
  EXPECT_TRUE(counted) << ::testing::PrintToString(part.warnings);
}

TEST(HostileStep, HugeTokenIsRefusedBeforeOpenCascadeReadsIt)
{
  // A 5,000,000-character string inside an entity: OpenCASCADE needs seconds and gigabytes for it,
  // the token scan refuses it at once, naming its line.
  TempDir dir;
  std::string text = readBytes(hostile("unresolved_point.step"));
  const std::string point = "#12 = CARTESIAN_POINT('',#999);";
  ASSERT_NE(text.find(point), std::string::npos);
  const size_t line =
      1 + static_cast<size_t>(std::count(text.begin(), text.begin() + text.find(point), '\n'));
  text.replace(text.find(point), point.size(),
               "#12 = CARTESIAN_POINT('" + std::string(5000000, 'A') + "',(0.,0.,0.));");
  writeBytes(dir / "token.step", text);
  EXPECT_TRUE(throwsOneLine<InputError>([&] { importFile(dir / "token.step"); },
                                        "'token.step' line " + std::to_string(line) +
                                            ": a token of 5000000 characters (at most 1000000 are read)"));
}

TEST(HostileStep, MemoryLimitStopsTheReader)
{
  ScopedEnv memory("SPIRA_IMPORT_MEMORY_MB", "1");
  EXPECT_TRUE(
      throwsOneLine<InputError>([] { importFile(hostile("unresolved_point.step")); },
                                "reading 'unresolved_point.step' needed more than the import's memory "
                                "limit of 1 MB"));
}

TEST(HostileStep, TimeLimitStopsTheReader)
{
  ScopedEnv time("SPIRA_IMPORT_TIMEOUT_S", "0.001");
  EXPECT_TRUE(throwsOneLine<InputError>([] { importFile(hostile("unresolved_point.step")); },
                                        "reading 'unresolved_point.step' took longer than the import's time "
                                        "limit of 0.001 s"));
}

TEST(HostileStep, BadLimitIsNamed)
{
  ScopedEnv time("SPIRA_IMPORT_TIMEOUT_S", "soon");
  EXPECT_TRUE(throwsOneLine<InputError>([] { importFile(hostile("unresolved_point.step")); },
                                        "SPIRA_IMPORT_TIMEOUT_S='soon' is not a positive number"));
}

TEST(HostileStep, CancelWhileTheHelperRunsStopsIt)
{
  TempDir dir;
  writeBoxes(25, dir / "boxes.step");
  CallbackProgress* self = nullptr;
  int reports = 0;
  CallbackProgress progress([&](double, std::string_view) {
    if (++reports == 1) self->cancel();
  });
  self = &progress;
  EXPECT_THROW(importPart(ioRegistry(), dir / "boxes.step", nullptr, progress), Cancelled);
  EXPECT_GE(reports, 1);
}

}  // namespace
}  // namespace spira::test
