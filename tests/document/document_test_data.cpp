#include "document/document_test_data.h"

#include <cmath>
#include <cstring>
#include <limits>

#include <nlohmann/json.hpp>

namespace spira::test {

TriangleMesh awkwardMesh()
{
  TriangleMesh m;
  const double tiny = 1e-300;
  const double denormal = std::numeric_limits<double>::denorm_min();
  const double huge = std::numeric_limits<double>::max();
  m.vertices = {Vec3(0.1, -0.0, 0.0),   Vec3(10.0, tiny, -0.0), Vec3(10.0, 10.0, denormal),
                Vec3(-0.0, 10.0, 0.3),  Vec3(0.1, 0.2, 20.0),   Vec3(10.0, 1.0 / 3.0, 20.0),
                Vec3(10.0, 10.0, huge), Vec3(M_PI, 10.0, 20.0)};
  // Four side walls of a square tube, two triangles each.
  for (int i = 0; i < 4; ++i) {
    const int a = i, b = (i + 1) % 4, c = 4 + (i + 1) % 4, d = 4 + i;
    m.faces.push_back({a, b, c});
    m.faces.push_back({a, c, d});
  }
  return m;
}

TriangleMesh tetrahedron(double edge)
{
  TriangleMesh m;
  const double h = edge * std::sqrt(2.0 / 3.0);
  m.vertices = {Vec3(0, 0, 0), Vec3(edge, 0, 0), Vec3(edge / 2, edge * std::sqrt(3.0) / 2, 0),
                Vec3(edge / 2, edge * std::sqrt(3.0) / 6, h)};
  m.faces = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  return m;
}

Part samplePart()
{
  Part p;
  p.name = "tube \xC3\xA9";  // non-ASCII on purpose
  p.sourcePath = "/parts/tube.stl";
  p.sourceUnit = LengthUnit::Inch;
  p.mesh = std::make_shared<const TriangleMesh>(awkwardMesh());
  p.T_world_part = transformFromXyzRpy(Vec3(100.1, -200.0, 0.3), Vec3(0.1, -0.2, 0.3));
  p.lowerBoundaryOverride = 1;
  return p;
}

CellRecord sampleCell()
{
  CellRecord c;
  c.name = "KR60 + DKP-400";
  c.robotUrdf = "robots/kr60/kr60.urdf";
  c.controller = ControllerFamily::FanucR30iB;
  c.T_world_robotbase = transformFromXyzZyx(Vec3(-1200.5, 0.1, 450.0), 0.5, -0.25, 1e-9);
  c.tool.T_flange_tcp = transformFromXyzRpy(Vec3(0, 35.2, 410.7), Vec3(0, -0.4363, 0));
  c.tool.nozzleRadius = 7.5;
  c.tool.nozzleLength = 22.1;
  c.tool.torchBodyRadius = 18.0;
  c.tool.torchBodyLength = 180.3;
  c.positionerUrdf = "robots/dkp400/dkp400.urdf";
  c.T_world_positioner = transformFromXyzRpy(Vec3(800.0, 0.0, 0.0), Vec3(0, 0, M_PI / 2));
  c.mounting = PartMounting::Positioner;
  c.robotBaseLink = "base";
  c.robotTipLink = "flange_tool0";
  c.j23Coupling = 1;
  c.positionerBaseLink = "pos_base";
  c.positionerTipLink = "pos_top";
  c.T_mount_part = transformFromXyzRpy(Vec3(1.5, -2.25, 30.0), Vec3(0, 0, 0.125));
  c.keepBuildVertical = false;
  c.cableTwistLimitDeg = 95.5;
  for (int i = 0; i < 6; ++i)
    c.robotAxes.push_back(CellAxis{"joint_a" + std::to_string(i + 1), i % 2 ? -1 : 1, i == 2 ? -90.0 : 0.0,
                                   -170.0 + i, 170.0 - i, 100.0 + 0.1 * i});
  c.positionerAxes.push_back(CellAxis{"tilt", 1, 0.0, -90.0, 90.0, 60.0});
  c.positionerAxes.push_back(CellAxis{"turn", -1, 0.5, -1e6, 1e6, 120.0});
  return c;
}

PlanSettings sampleSettings()
{
  PlanSettings s;
  s.decomposerId = "decomposer.geodesic";
  s.closureFinderId = "closure.zone";
  ParamSet process;
  process.set("travel_speed", 8.5);
  process.set("wire_feed", 2.0);  // integral double must stay a double
  process.set("layer_height", 0.1);
  process.set("offset", -0.0);
  process.set("layers", std::int64_t{-3});
  process.set("big", std::int64_t{1} << 62);
  process.set("arc", true);
  process.set("dwell", false);
  process.set("mode", std::string("cmt"));
  process.set("empty", std::string());
  s.params[PlanSettings::kProcessSection] = process;
  ParamSet geo;
  geo.set("smoothing", 1e-300);
  geo.set("output", std::string("/tmp/out dir/\xE2\x82\xAC"));
  s.params["decomposer.geodesic"] = geo;
  return s;
}

Trajectory sampleTrajectory(int points)
{
  Trajectory t;
  for (int i = 0; i < points; ++i) {
    TrajectoryPoint p;
    const double a = 0.1 * i;
    p.position = Vec3(std::cos(a) * 30.0, std::sin(a) * 30.0, 0.05 * i);
    p.normal = Vec3(std::cos(a), std::sin(a), -0.0);
    p.tangent = Vec3(-std::sin(a), std::cos(a), 0.0);
    p.build = p.normal.cross(p.tangent);
    p.path = i / 7;
    p.revolution = i / 5;
    p.generatrix = i % 5;
    p.height = 1.0 + 1e-12 * i;
    p.travelSpeed = 10.0 / 3.0;
    p.wireFeed = 0.1 * i;
    p.arcOn = i % 3 != 0;
    t.points.push_back(p);
    t.extra["dwell"].push_back(i == 0 ? -0.0 : 0.25 * i);
  }
  return t;
}

Generatrices sampleGeneratrices()
{
  Generatrices g;
  for (int k = 0; k < 4; ++k) {
    Polyline l;
    for (int i = 0; i <= k + 1; ++i) l.push_back(Vec3(k, 0.1 * i, i / 3.0));
    g.lines.push_back(l);
  }
  for (const Polyline& l : g.lines) {
    std::vector<Vec3> n;
    for (size_t i = 0; i < l.size(); ++i) n.push_back(Vec3(1.0 / 3.0, -0.0, 0.1 * i).normalized());
    g.normals.push_back(n);
  }
  g.lines.push_back(Polyline());  // an empty line survives too
  g.normals.push_back({});
  g.hasClosurePoint = true;
  g.closurePoint = Vec3(0.1, 0.2, 0.30000000000000004);
  return g;
}

ThermalStageResult sampleThermal(int points)
{
  ThermalStageResult t;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 2 * points; ++i) t.nodes.push_back(Vec3(i / 2, 0.0, 2.0 * (i % 2)));
  for (int i = 0; i + 3 < 2 * points; i += 2) {
    t.triangles.push_back({i, i + 2, i + 1});
    t.triangles.push_back({i + 1, i + 2, i + 3});
  }
  for (int i = 0; i < points; ++i) {
    t.pointNode.push_back(2 * i + 1);
    t.peak.push_back(1500.0 + i);
    t.interpass.push_back(i == 0 ? nan : 300.0 + 10.0 * i);
    t.timeAboveMelt.push_back(0.25 * i);
    t.poolLength.push_back(3.0 + 0.1 * i);
    t.bond.push_back(0.5 * i);
    t.risk.push_back(i % 3 == 0 ? 1 : 0);
  }
  for (size_t n = 0; n < t.nodes.size(); ++n) t.nodePeak.push_back(1400.0 + static_cast<double>(n));
  t.probeNodes = {3};
  t.probeTimes = {0.0, 1.0, 2.0};
  t.probeTemperatures = {{20.0, 1600.0, 900.5}};
  std::vector<float> early(t.nodes.size(), std::numeric_limits<float>::quiet_NaN()), late(t.nodes.size());
  for (size_t n = 0; n < t.nodes.size(); ++n) {
    if (n < t.nodes.size() / 2) early[n] = 20.0f + static_cast<float>(n);
    late[n] = 1500.0f - static_cast<float>(n);
  }
  t.frames = ThermalFrameSet::quantise({1.0, 2.0}, {early, late});
  t.replanned = std::make_shared<const Trajectory>(sampleTrajectory(points + 2));
  return t;
}

DocumentState fullState()
{
  DocumentState s;
  s.part = std::make_shared<const Part>(samplePart());
  s.substrate = std::make_shared<const Substrate>(Substrate::fromMesh(
      std::make_shared<const TriangleMesh>(tetrahedron(50.0)), "pipe", "/parts/pipe.obj"));
  s.cell = std::make_shared<const CellRecord>(sampleCell());
  s.settings = std::make_shared<const PlanSettings>(sampleSettings());
  FieldResult f;
  f.kind = "geodesic_distance";
  f.source = "heat method from loop 1";
  f.values = {0.0, -0.0, 0.1, 1e-300, 3.5, 7.25, std::numeric_limits<double>::infinity(), 2.0};
  FieldStageReport field{"geodesic_distance", {{"field", 0.25}}, Vec3(0.0, 0.0, 60.0), 61.5};
  s.results.setField(std::make_shared<const FieldResult>(f), std::make_shared<const FieldStageReport>(field));
  s.results.setGeneratrices(
      std::make_shared<const Generatrices>(sampleGeneratrices()),
      std::make_shared<const GeneratricesStageReport>(GeneratricesStageReport{2, 9.5, 10.25}));
  SpiralStageReport spiral;
  spiral.strategy = "geodesic";
  spiral.points = 20;
  spiral.hMin = 1.8;
  spiral.hMax = 2.2;
  spiral.warnings = {"a warning"};
  spiral.depositCheck.flaggedPoints = {
      {3, "jump", std::numeric_limits<double>::infinity(), Vec3(1.0, 2.0, 3.0)}};
  s.results.setSpiral(std::make_shared<const Trajectory>(sampleTrajectory(20)),
                      std::make_shared<const SpiralStageReport>(spiral));
  ProcessStageReport process;
  process.wireLength = 1234.5;
  s.results.setProcess(std::make_shared<const Trajectory>(sampleTrajectory(23)),
                       std::make_shared<const ProcessStageReport>(process));
  ThermalStageReport thermal;
  thermal.material = "G3Si1";
  thermal.maxInterpass = 520.0;
  thermal.limitMet = false;
  s.results.setThermal(std::make_shared<const ThermalStageResult>(sampleThermal(23)),
                       std::make_shared<const ThermalStageReport>(thermal));
  KinematicsStageReport kinematics;
  kinematics.motion.cell = "sample cell";
  kinematics.motion.jointSpeed.perAxis["A1"] = {std::numeric_limits<double>::infinity(), std::nullopt};
  kinematics.seconds = 0.5;
  s.results.setKinematics(std::make_shared<const KinematicsResult>(sampleKinematics(7)),
                          std::make_shared<const KinematicsStageReport>(kinematics));
  s.results.setExport(
      std::make_shared<const ExportStageResult>(ExportStageResult{"export.krl", {"a.src", "a.dat"}}));
  return s;
}

bool bitwiseEqual(const std::vector<Vec3>& a, const std::vector<Vec3>& b)
{
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0);
}

}  // namespace spira::test
