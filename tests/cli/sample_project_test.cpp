// The bundled sample project, resources/samples/dome.spira: the dome sample on the FANUC
// positioner cell with the default settings. It must hold exactly that (its robot files found
// relative to it, wherever the checkout is) and plan feasibly from the command line.
// SPIRA_WRITE_SAMPLES=1 rewrites it from the sample part and cell first.
#include <gtest/gtest.h>

#include <cstdlib>
#include <memory>

#include "builtin_plugins.h"
#include "cli_runner.h"
#include "spira/base/progress.h"
#include "spira/document/document.h"
#include "spira/document/project_file.h"
#include "spira/io/import_service.h"
#include "spira/robotcell/cell_file.h"
#include "support/test_support.h"

namespace fs = std::filesystem;

namespace spira::test {
namespace {

fs::path resource(const std::string& sub)
{
  return sourceDir() / "resources" / sub;
}

// What the sample holds: the part as File > Import Part reads it, the cell as the Cell dock loads it.
DocumentState expectedSample()
{
  NullProgress progress;
  ImportedPart imported = importPart(builtinRegistry(), resource("samples/dome.stl"), nullptr, progress);
  Document doc;
  Part part;
  part.name = "dome";
  part.sourcePath = "dome.stl";
  part.sourceUnit = imported.sourceUnit;
  part.mesh = std::make_shared<const TriangleMesh>(std::move(imported.mesh));
  doc.setPart(part);
  doc.setCell(readCellFile(resource("cells/fanuc_m20ia_positioner.cell")));
  return doc.state();
}

TEST(SampleProject, DomeOnTheFanucPositionerCellPlansFeasibly)
{
  const fs::path sample = resource("samples/dome.spira");
  const DocumentState expected = expectedSample();
  if (const char* write = std::getenv("SPIRA_WRITE_SAMPLES"); write && std::string(write) == "1")
    saveProject(expected, sample);

  const DocumentState shipped = loadProject(sample);
  ASSERT_TRUE(shipped.part);
  EXPECT_EQ(*shipped.part, *expected.part);
  ASSERT_TRUE(shipped.cell);
  EXPECT_EQ(*shipped.cell, *expected.cell)
      << "robot URDF " << shipped.cell->robotUrdf << ", expected " << expected.cell->robotUrdf;
  EXPECT_EQ(*shipped.settings, *expected.settings);

  TempDir dir;
  const CliRun r = runCli({"plan", sample.string(), "-o", (dir / "plan").string()});
  EXPECT_EQ(r.exitCode, 0) << r.err << r.out;
  EXPECT_NE(r.out.find("feasible: "), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(dir / "plan" / "joints.csv"));
}

}  // namespace
}  // namespace spira::test
