// Scans (issue 19: load, filter and align a 1,000,000-point scan to a 100,000-triangle part in < 3 s):
// the real T-junction of tests/data/real subdivided to 100,000+ triangles, a simulated scan of it with
// 1,000,000 points (0.05 mm noise, moved 3 mm and 2 deg) written as binary PLY, then read, cleaned of
// stray points and registered, and its deviation measured.
// Resume (issue 19: < 1 s on the dome): the bundled dome planned, built to half way 8 % short over its
// first 30 % and scanned with 1,000,000 points, then the scan read, the top edge measured and the rest
// re-planned.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include "best_of.h"
#include "builtin_plugins.h"
#include "spira/base/units.h"
#include "spira/io/import_service.h"
#include "spira/mesh/mesh_report.h"
#include "spira/planning/planner.h"
#include "spira/scan/scan_alignment.h"
#include "spira/scan/scan_deviation.h"
#include "spira/scan/scan_processing.h"
#include "spira/scan/scan_reader.h"
#include "spira/scan/scan_resume.h"
#include "spira/scan/scan_simulator.h"
#include "spira/scan/scan_writer.h"
#include "support/test_support.h"

namespace {

using namespace spira;

// Each triangle into four at its edges' midpoints (shared between neighbours): same surface, 4x faces.
TriangleMesh subdivided(const TriangleMesh& m)
{
  TriangleMesh out;
  out.vertices = m.vertices;
  std::map<std::pair<int, int>, int> middle;
  const auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    const auto it = middle.find(key);
    if (it != middle.end()) return it->second;
    out.vertices.push_back(0.5 * (m.vertices[size_t(a)] + m.vertices[size_t(b)]));
    return middle[key] = int(out.vertices.size() - 1);
  };
  for (const Face& f : m.faces) {
    const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    out.faces.push_back({f[0], ab, ca});
    out.faces.push_back({ab, f[1], bc});
    out.faces.push_back({ca, bc, f[2]});
    out.faces.push_back({ab, bc, ca});
  }
  return out;
}

double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The simulated scan has one profile per path point; a real line scanner sees the wall far more
// densely. Scans of the same wall with other noise seeds, put together, make up the point count.
PointCloud denseScanOfBuild(const Trajectory& plan, size_t at, const std::vector<double>& shortfall,
                            size_t points)
{
  PointCloud out;
  for (std::uint64_t seed = 1; out.size() < points; ++seed) {
    const PointCloud one =
        scanOfBuild(plan, at, shortfall, kDefaultBeadWidth, 3, 2.0 * kDefaultBeadWidth, 0.05, seed);
    out.points.insert(out.points.end(), one.points.begin(), one.points.end());
  }
  out.points.resize(points);
  return out;
}

void benchResume()
{
  NullProgress progress;
  const TriangleMesh dome =
      importPart(builtinRegistry(), test::sourceDir() / "resources/samples/dome.stl", nullptr, progress).mesh;
  const MeshReport report = validateMesh(dome);
  const Trajectory plan = planPart(builtinRegistry(), PlanRequest(dome, report), progress).spiral.trajectory;
  const size_t at = plan.size() / 2;
  DepositErrors errors;
  errors.relative = -0.08;
  errors.until = 0.3;
  const std::vector<double> truth = builtShortfall(plan, at, errors);
  test::TempDir dir;
  {
    std::ofstream out(dir / "wall.ply", std::ios::binary);
    out << pointCloudPly(denseScanOfBuild(plan, at, truth, 1000000));
  }
  double tRead = 0, tMeasure = 0, tResume = 0;
  size_t points = 0;
  MeasuredEdge edge;
  Resumed resumed;
  const double total = bestOf(3, [&] {
    auto t0 = std::chrono::steady_clock::now();
    const PointCloud scan = readScan(builtinRegistry(), dir / "wall.ply", progress);
    points = scan.size();
    tRead = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    edge = measureTopEdge(plan, at, scan, kDefaultBeadWidth);
    tMeasure = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    resumed = resumeFromEdge(plan, at, edge, ResumeSettings{1.8, 2.2, ProcessSettings{}});
    tResume = seconds(t0);
  });
  double off = 0.0;
  for (size_t e = 0; e < edge.points.size(); ++e)
    off = std::max(off, std::abs(edge.shortfall[e] - truth[edge.points[e]]));
  std::printf(
      "resume on the dome: %zu plan points, at %zu, scan %zu points: read + measure + resume %.3f s (best of "
      "3; "
      "read %.3f, measure %.3f, resume %.3f); %zu edge points measured within %.4f mm; %s\n",
      plan.size(), at, points, total, tRead, tMeasure, tResume, edge.points.size(), off,
      resumed.report.summary().c_str());
}

}  // namespace

// "bench_scan resume" runs the resume case alone.
int main(int argc, char** argv)
{
  benchResume();
  if (argc > 1 && std::string(argv[1]) == "resume") return 0;
  NullProgress progress;
  TriangleMesh part =
      importPart(builtinRegistry(), test::sourceDir() / "tests/data/real/junction_waam_mm.stl", nullptr,
                 progress)
          .mesh;
  while (part.faceCount() < 100000) part = subdivided(part);
  // The spacing that gives about a million points.
  const double spacing = std::sqrt(part.area() / 1.0e6);
  ScanErrors errors;
  errors.noiseMm = 0.05;
  errors.misalignment.linear() =
      Eigen::AngleAxisd(degToRad(2.0), Vec3(1, 1, 1).normalized()).toRotationMatrix();
  errors.misalignment.translation() = Vec3(2.0, -2.0, 1.0);
  const PointCloud simulated = simulateSurfaceScan(part, spacing, errors, 11);
  test::TempDir dir;
  {
    std::ofstream out(dir / "scan.ply", std::ios::binary);
    out << pointCloudPly(simulated);
  }
  double tRead = 0, tFilter = 0, tAlign = 0, tDeviation = 0;
  AlignResult fit;
  size_t kept = 0;
  const double total = bestOf(3, [&] {
    auto t0 = std::chrono::steady_clock::now();
    PointCloud scan = readScan(builtinRegistry(), dir / "scan.ply", progress);
    tRead = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    scan = filterScan(scan, ScanFilterSettings{});
    kept = scan.size();
    tFilter = seconds(t0);
    t0 = std::chrono::steady_clock::now();
    fit = alignScan(scan, part, Transform::Identity(), AlignSettings{}, progress);
    tAlign = seconds(t0);
  });
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<double> d = scanDeviation(transformed(simulated, fit.T_part_scan), part, progress);
  tDeviation = seconds(t0);
  const Transform error = fit.T_part_scan * errors.misalignment;
  std::printf(
      "part %zu triangles, scan %zu points (%zu kept): load + filter + align %.3f s (best of 3; read %.3f, "
      "filter %.3f, align %.3f); back within %.4f mm and %.4f deg; deviation of every point %.3f s, RMS %.4f "
      "mm\n",
      part.faceCount(), simulated.size(), kept, total, tRead, tFilter, tAlign, error.translation().norm(),
      radToDeg(Eigen::AngleAxisd(error.linear()).angle()), tDeviation, deviationStats(d).rms);
  return 0;
}
