#include "spira/planning/solid_wall.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "spira/base/error.h"

namespace spira {

bool isClosedSolid(const MeshReport& report)
{
  return report.boundaryLoops.empty() && report.componentCount == 1 && report.isPlannable();
}

std::vector<std::string> beadWidthWarnings(const WallThickness& t, double beadWidth)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2);
  if (t.median > kThickWallBeadRatio * beadWidth)
    s << "the wall is " << t.median << " mm thick, more than " << kThickWallBeadRatio << " x the bead width ("
      << beadWidth << " mm): one bead per layer on the mid-surface lays a wall about " << beadWidth
      << " mm wide; widen the bead (--bead-width) or thin the wall";
  else if (t.median < kThinWallBeadRatio * beadWidth)
    s << "the wall is " << t.median << " mm thick, less than " << kThinWallBeadRatio << " x the bead width ("
      << beadWidth << " mm): the deposit will be about " << beadWidth
      << " mm wide, so machine it back or narrow the bead (--bead-width)";
  else
    return {};
  return {s.str()};
}

SolidWall solidWallOf(const ThinWallAnalysis& analysis, size_t solidFaces, double beadWidth)
{
  if (analysis.kind != SolidKind::ThinWalled)
    throw InputError(
        "the part is a closed solid and cannot be planned: " + analysis.reason,
        "Spira lays one bead along a thin wall: give it the wall's mid-surface, or one of its skins, "
        "as a surface open at the base (a solid body for vase-mode printing is not a wall; export its "
        "outer surface without the floor and rim)");
  SolidWall w;
  w.thickness = analysis.thickness;
  w.wallAreaFraction = analysis.wallAreaFraction;
  w.beadWidth = beadWidth;
  w.solidFaces = solidFaces;
  w.skinFaces = analysis.skinFaces;
  w.midSurface = std::make_shared<const TriangleMesh>(analysis.midSurface);
  w.warnings = beadWidthWarnings(w.thickness, beadWidth);
  return w;
}

namespace {

// A face lying within about 14 degrees of horizontal is part of a plate, not of a rising wall.
constexpr double kFlatNormalZ = 0.97;

double flatShare(const TriangleMesh& mesh)
{
  double flat = 0.0, total = 0.0;
  for (size_t f = 0; f < mesh.faceCount(); ++f) {
    const double a = mesh.faceArea(f);
    total += a;
    if (std::abs(mesh.faceNormal(f).z()) >= kFlatNormalZ) flat += a;
  }
  return total > 0.0 ? flat / total : 0.0;
}

}  // namespace

void requireOneWall(const SolidWall& wall, const MeshReport& midReport)
{
  const size_t loops = midReport.boundaryLoops.size();
  if (midReport.componentCount == 1 && midReport.isPlannable() && loops > 0) return;
  std::ostringstream what;
  what << std::fixed << std::setprecision(2) << "the part is a thin-walled solid (wall "
       << wall.thickness.median << " mm thick) but not one wall: its mid-surface ";
  if (midReport.componentCount != 1)
    what << "parts into " << midReport.componentCount << " pieces";
  else if (loops == 0)
    what << "is closed all round (a hollow body with no open end)";
  else
    what << "folds onto itself where walls meet";
  const double flat = flatShare(*wall.midSurface);
  if (flat >= 0.1)
    what << ", and " << std::setprecision(0) << 100.0 * flat
         << " % of it lies flat (a flange, a floor or a lid: a plate, not a wall a spiral rises along)";
  throw InputError(
      what.str(),
      "give Spira the wall alone: its mid-surface, or one of its skins, as a surface open at the base, "
      "without flanges, floors or lids (for a tube on a flange, the tube from the flange's top up; "
      "lay or machine the flange separately)");
}

SolidSurface plannableMidSurface(const TriangleMesh& solid, double beadWidth)
{
  SolidSurface s;
  s.wall = solidWallOf(analyseClosedSolid(solid), solid.faceCount(), beadWidth);
  s.report = validateMesh(*s.wall.midSurface);
  requireOneWall(s.wall, s.report);
  return s;
}

std::string SolidWall::summary() const
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << "thin-walled solid: wall " << thickness.median << " mm thick ("
    << thickness.thinnest << " .. " << thickness.thickest << " mm), bead width " << beadWidth
    << " mm: planned on its mid-surface";
  return s.str();
}

}  // namespace spira
