#include <iostream>

#include "cli_common.h"
#include "spira/base/error.h"
#include "spira/base/units.h"
#include "spira/io/mesh_writers.h"
#include "spira/mesh/mesh_primitives.h"

namespace spira::cli {
namespace {

// The bundled samples are made here, by code, so they can be regenerated and checked.
// Sizes are typical of the source thesis' lab parts; edges about 2 mm.
TriangleMesh makeSample(const std::string& name)
{
  constexpr double kEdge = 2.0;
  if (name == "open-cylinder") {
    const double r = 50.0, h = 100.0;
    return makeOpenCylinder(r, h, segmentsForEdge(r, kEdge), static_cast<int>(h / kEdge));
  }
  if (name == "dome") {
    const double r = 60.0;
    const int segments = segmentsForEdge(r, kEdge);
    return makeHemisphere(r, segments, segments / 4);
  }
  if (name == "cone") {
    const double r0 = 60.0, r1 = 40.0, h = 100.0;
    return makeOpenCone(r0, r1, h, segmentsForEdge(r0, kEdge), static_cast<int>(h / kEdge));
  }
  if (name == "bent-tube") {
    // The source's quarter torus (004_bd0df31205c0c3c0.txt §2.3): bend radius 50, tube radius 15.
    const double bend = 50.0, r = 15.0, angle = 0.5 * kPi;
    return makeBentTube(bend, r, angle, segmentsForEdge(r, kEdge), static_cast<int>(bend * angle / kEdge));
  }
  if (name == "torus-on-pipe") {
    // The source's feature on a 64 mm pipe (004_bd0df31205c0c3c0.txt §2.2.3): the same quarter torus
    // from where it leaves the cylinder of radius 32 about y (plan it with --substrate cylinder:32,y).
    const double bend = 50.0, r = 15.0, angle = 0.5 * kPi;
    return makeTorusOnCylinder(bend, r, 32.0, angle, segmentsForEdge(r, kEdge),
                               static_cast<int>(bend * angle / kEdge));
  }
  throw InputError("unknown sample '" + name + "'",
                   "use one of: open-cylinder, dome, cone, bent-tube, torus-on-pipe");
}

}  // namespace

int cmdSample(const std::vector<std::string>& argv)
{
  Args args = splitArgs(argv);
  if (args.takeSwitch("--help")) {
    std::cout
        << "usage: spira-cli sample NAME -o FILE\n\n"
           "Writes a sample part made in code: open-cylinder (R 50, H 100 mm), dome (hemisphere R 60 mm),\n"
           "cone (R 60 to 40, H 100 mm), bent-tube (quarter torus, bend R 50, tube r 15 mm),\n"
           "torus-on-pipe (the same bend added onto a pipe of radius 32 mm about y: plan it with\n"
           "--substrate cylinder:32,y).\n"
           "The format follows FILE's extension (.stl, .obj, .ply).\n";
    return kExitOk;
  }
  const std::string out = args.takeOption("-o");
  const auto positional = args.finish("sample", 1, 1);
  if (out.empty()) throw UsageError("'sample' needs an output file", "write -o FILE.stl");
  const TriangleMesh mesh = makeSample(positional[0]);
  writeMesh(mesh, out);
  std::cout << "wrote " << out << " (" << mesh.vertexCount() << " vertices, " << mesh.faceCount()
            << " triangles)\n";
  return kExitOk;
}

}  // namespace spira::cli
