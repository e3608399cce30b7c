#include <algorithm>
#include <type_traits>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/document/results.h"
#include "spira/document/stage_report_codec.h"
#include "spira/document/thermal_result.h"
#include "spira/document/trajectory_codec.h"
#include "spira/io/json_codec.h"

namespace spira {

namespace {

// 2: the kinematics result is typed (kinematics_result.h); schema 1 held a JSON payload that
// nothing produced, and it is dropped on reading (the stage is recomputed). The thermal stage's
// result came later without a new schema: it is optional, a file without it reads as not simulated,
// and an earlier version opening a file with it ignores it (the stage's report too).
constexpr int kResultsSchema = 2;

// The codecs below list every member of these types. When a member is added, these fail to
// compile as a reminder to store it too (and to bump kResultsSchema if old files lack it).
static_assert(sizeof(void*) != 8 || sizeof(TrajectoryPoint) == 144, "update trajectoryToJson/FromJson");
static_assert(sizeof(void*) != 8 || sizeof(Generatrices) == 104, "update generatricesToJson/FromJson");
static_assert(sizeof(void*) != 8 || sizeof(JointPoint) == 272, "update jointsToJson/FromJson");
static_assert(sizeof(void*) != 8 || sizeof(KinematicsCheck) == 32, "update kinematicsToJson/FromJson");

}  // namespace

nlohmann::json trajectoryToJson(const Trajectory& t)
{
  const size_t n = t.points.size();
  std::vector<Vec3> position(n), normal(n), tangent(n), build(n);
  std::vector<std::int32_t> path(n), revolution(n), generatrix(n), arcOn(n);
  std::vector<double> height(n), travelSpeed(n), wireFeed(n);
  for (size_t i = 0; i < n; ++i) {
    const TrajectoryPoint& p = t.points[i];
    position[i] = p.position;
    normal[i] = p.normal;
    tangent[i] = p.tangent;
    build[i] = p.build;
    path[i] = p.path;
    revolution[i] = p.revolution;
    generatrix[i] = p.generatrix;
    arcOn[i] = p.arcOn ? 1 : 0;
    height[i] = p.height;
    travelSpeed[i] = p.travelSpeed;
    wireFeed[i] = p.wireFeed;
  }
  nlohmann::json extra = nlohmann::json::object();
  for (const auto& [name, values] : t.extra) extra[name] = codec::doublesToBlob(values);
  return {{"count", n},
          {"position", codec::vec3sToBlob(position)},
          {"normal", codec::vec3sToBlob(normal)},
          {"tangent", codec::vec3sToBlob(tangent)},
          {"build", codec::vec3sToBlob(build)},
          {"path", codec::intsToBlob(path)},
          {"revolution", codec::intsToBlob(revolution)},
          {"generatrix", codec::intsToBlob(generatrix)},
          {"arc_on", codec::intsToBlob(arcOn)},
          {"height", codec::doublesToBlob(height)},
          {"travel_speed", codec::doublesToBlob(travelSpeed)},
          {"wire_feed", codec::doublesToBlob(wireFeed)},
          {"extra", std::move(extra)}};
}

namespace {

template <class T>
std::vector<T> sized(std::vector<T> v, size_t n, const std::string& what)
{
  if (v.size() != n)
    throw InputError(what + ": " + std::to_string(v.size()) + " values for " + std::to_string(n) + " points",
                     "the project file is damaged");
  return v;
}

}  // namespace

Trajectory trajectoryFromJson(const nlohmann::json& j, const std::string& what)
{
  const std::int64_t count = codec::intField(j, "count", what);
  if (count < 0) throw InputError(what + ": negative point count", "the project file is damaged");
  const auto n = static_cast<size_t>(count);
  auto vec3s = [&](const char* key) {
    return sized(codec::blobToVec3s(codec::field(j, key, what), what + " " + key), n, what);
  };
  auto ints = [&](const char* key) {
    return sized(codec::blobToInts(codec::field(j, key, what), what + " " + key), n, what);
  };
  auto doubles = [&](const char* key) {
    return sized(codec::decodeDoubleBlob(codec::field(j, key, what), what + " " + key), n, what);
  };
  const auto position = vec3s("position"), normal = vec3s("normal"), tangent = vec3s("tangent"),
             build = vec3s("build");
  const auto path = ints("path"), revolution = ints("revolution"), generatrix = ints("generatrix"),
             arcOn = ints("arc_on");
  const auto height = doubles("height"), travelSpeed = doubles("travel_speed"),
             wireFeed = doubles("wire_feed");
  Trajectory t;
  t.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    TrajectoryPoint& p = t.points[i];
    p.position = position[i];
    p.normal = normal[i];
    p.tangent = tangent[i];
    p.build = build[i];
    p.path = path[i];
    p.revolution = revolution[i];
    p.generatrix = generatrix[i];
    p.arcOn = arcOn[i] != 0;
    p.height = height[i];
    p.travelSpeed = travelSpeed[i];
    p.wireFeed = wireFeed[i];
  }
  const auto& extra = codec::field(j, "extra", what);
  if (!extra.is_object())
    throw InputError(what + ": 'extra' is not an object", "the project file is damaged");
  for (auto it = extra.begin(); it != extra.end(); ++it)
    t.extra[it.key()] =
        sized(codec::decodeDoubleBlob(it.value(), what + " " + it.key()), n, what + " " + it.key());
  return t;
}

namespace {

nlohmann::json generatricesToJson(const Generatrices& g)
{
  nlohmann::json lines = nlohmann::json::array();
  for (const Polyline& l : g.lines) lines.push_back(codec::vec3sToBlob(l));
  nlohmann::json normals = nlohmann::json::array();
  for (const auto& n : g.normals) normals.push_back(codec::vec3sToBlob(n));
  nlohmann::json j = {{"lines", std::move(lines)},
                      {"normals", std::move(normals)},
                      {"has_closure_point", g.hasClosurePoint},
                      {"closure_point", codec::vec3sToBlob({g.closurePoint})}};
  if (!g.guide.empty()) j["guide"] = codec::vec3sToBlob(g.guide);
  return j;
}

Generatrices generatricesFromJson(const nlohmann::json& j, const std::string& what)
{
  Generatrices g;
  const auto& lines = codec::field(j, "lines", what);
  if (!lines.is_array()) throw InputError(what + ": 'lines' is not an array", "the project file is damaged");
  for (const auto& l : lines) g.lines.push_back(codec::blobToVec3s(l, what + " line"));
  const auto& normals = codec::field(j, "normals", what);
  if (!normals.is_array())
    throw InputError(what + ": 'normals' is not an array", "the project file is damaged");
  for (const auto& n : normals) g.normals.push_back(codec::blobToVec3s(n, what + " normals"));
  g.hasClosurePoint = codec::boolField(j, "has_closure_point", what);
  g.closurePoint = sized(codec::blobToVec3s(codec::field(j, "closure_point", what), what), 1, what)[0];
  if (j.contains("guide")) g.guide = codec::blobToVec3s(j["guide"], what + " guide");
  return g;
}

nlohmann::json limitsToJson(const std::vector<AxisLimit>& limits)
{
  nlohmann::json names = nlohmann::json::array();
  std::vector<double> numbers;
  for (const AxisLimit& a : limits) {
    names.push_back(a.name);
    numbers.insert(numbers.end(), {a.minDeg, a.maxDeg, a.maxSpeedDegPerS});
  }
  return {{"names", std::move(names)}, {"min_max_speed_deg", codec::doublesToBlob(numbers)}};
}

std::vector<AxisLimit> limitsFromJson(const nlohmann::json& j, const std::string& what)
{
  const auto& names = codec::field(j, "names", what);
  if (!names.is_array()) throw InputError(what + ": 'names' is not an array", "the project file is damaged");
  const auto numbers = sized(codec::decodeDoubleBlob(codec::field(j, "min_max_speed_deg", what), what),
                             3 * names.size(), what);
  std::vector<AxisLimit> out(names.size());
  for (size_t k = 0; k < out.size(); ++k) {
    if (!names[k].is_string())
      throw InputError(what + ": an axis name is not text", "the project file is damaged");
    out[k] = AxisLimit{names[k].get<std::string>(), numbers[3 * k], numbers[3 * k + 1], numbers[3 * k + 2]};
  }
  return out;
}

nlohmann::json jointsToJson(const JointTrajectory& t)
{
  const size_t n = t.points.size();
  std::vector<double> robot, external, pose, dexterity;
  std::vector<std::int32_t> status(n), turn(n), reachable(n), collision(n), configIndex(n), abbConf;
  const bool abb = t.controller == "abb_irc5";
  if (abb) abbConf.reserve(4 * n);
  robot.reserve(6 * n);
  external.reserve(2 * n);
  pose.reserve(12 * n);
  // Configuration labels repeat along a path: stored once each, indexed per point.
  std::vector<std::string> configs;
  for (size_t i = 0; i < n; ++i) {
    const JointPoint& p = t.points[i];
    robot.insert(robot.end(), p.robotDeg.begin(), p.robotDeg.end());
    external.insert(external.end(), p.externalDeg.begin(), p.externalDeg.end());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) pose.push_back(p.baseTcp.matrix()(r, c));
    dexterity.push_back(p.dexterity);
    status[i] = p.kukaStatus;
    turn[i] = p.kukaTurn;
    reachable[i] = p.reachable ? 1 : 0;
    collision[i] = p.collision ? 1 : 0;
    auto it = std::find(configs.begin(), configs.end(), p.fanucConfig);
    if (it == configs.end()) it = configs.insert(configs.end(), p.fanucConfig);
    configIndex[i] = static_cast<std::int32_t>(it - configs.begin());
    if (abb) abbConf.insert(abbConf.end(), p.abbConf.begin(), p.abbConf.end());
  }
  nlohmann::json j = {{"count", n},
                      {"controller", t.controller},
                      {"cell_name", t.cellName},
                      {"has_positioner", t.hasPositioner},
                      {"robot_limits", limitsToJson({t.robotLimits.begin(), t.robotLimits.end()})},
                      {"external_limits", limitsToJson({t.externalLimits.begin(), t.externalLimits.end()})},
                      {"robot_deg", codec::doublesToBlob(robot)},
                      {"external_deg", codec::doublesToBlob(external)},
                      {"base_tcp", codec::doublesToBlob(pose)},
                      {"dexterity", codec::doublesToBlob(dexterity)},
                      {"kuka_status", codec::intsToBlob(status)},
                      {"kuka_turn", codec::intsToBlob(turn)},
                      {"reachable", codec::intsToBlob(reachable)},
                      {"collision", codec::intsToBlob(collision)},
                      {"fanuc_configs", configs},
                      {"fanuc_config", codec::intsToBlob(configIndex)}};
  // Only ABB trajectories carry confdata, so that other projects keep their file byte for byte.
  if (abb) {
    j["abb_conf"] = codec::intsToBlob(abbConf);
    std::vector<double> tcp;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) tcp.push_back(t.flangeTcp.matrix()(r, c));
    j["flange_tcp"] = codec::doublesToBlob(tcp);
  }
  return j;
}

JointTrajectory jointsFromJson(const nlohmann::json& j, const std::string& what)
{
  const std::int64_t count = codec::intField(j, "count", what);
  if (count < 0) throw InputError(what + ": negative point count", "the project file is damaged");
  const auto n = static_cast<size_t>(count);
  auto doubles = [&](const char* key, size_t per) {
    return sized(codec::decodeDoubleBlob(codec::field(j, key, what), what + " " + key), per * n, what);
  };
  auto ints = [&](const char* key) {
    return sized(codec::blobToInts(codec::field(j, key, what), what + " " + key), n, what);
  };
  JointTrajectory t;
  t.controller = codec::stringField(j, "controller", what);
  t.cellName = codec::stringField(j, "cell_name", what);
  t.hasPositioner = codec::boolField(j, "has_positioner", what);
  const auto robotLimits = limitsFromJson(codec::field(j, "robot_limits", what), what + " robot limits");
  const auto externalLimits =
      limitsFromJson(codec::field(j, "external_limits", what), what + " external limits");
  if (robotLimits.size() != t.robotLimits.size() || externalLimits.size() != t.externalLimits.size())
    throw InputError(what + ": wrong number of axis limits", "the project file is damaged");
  std::copy(robotLimits.begin(), robotLimits.end(), t.robotLimits.begin());
  std::copy(externalLimits.begin(), externalLimits.end(), t.externalLimits.begin());
  const auto robot = doubles("robot_deg", 6), external = doubles("external_deg", 2),
             pose = doubles("base_tcp", 12), dexterity = doubles("dexterity", 1);
  const auto status = ints("kuka_status"), turn = ints("kuka_turn"), reachable = ints("reachable"),
             collision = ints("collision"), configIndex = ints("fanuc_config");
  const auto& configs = codec::field(j, "fanuc_configs", what);
  if (!configs.is_array())
    throw InputError(what + ": 'fanuc_configs' is not an array", "the project file is damaged");
  if (j.contains("flange_tcp")) {
    const auto tcp =
        sized(codec::decodeDoubleBlob(codec::field(j, "flange_tcp", what), what + " flange_tcp"), 12, what);
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) t.flangeTcp.matrix()(r, c) = tcp[static_cast<size_t>(4 * r + c)];
  }
  std::vector<std::int32_t> abbConf;
  if (j.contains("abb_conf"))
    abbConf = sized(codec::blobToInts(codec::field(j, "abb_conf", what), what + " abb_conf"), 4 * n, what);
  t.points.resize(n);
  for (size_t i = 0; i < n; ++i) {
    JointPoint& p = t.points[i];
    if (!abbConf.empty())
      std::copy_n(abbConf.begin() + static_cast<std::ptrdiff_t>(4 * i), 4, p.abbConf.begin());
    std::copy_n(robot.begin() + static_cast<std::ptrdiff_t>(6 * i), 6, p.robotDeg.begin());
    std::copy_n(external.begin() + static_cast<std::ptrdiff_t>(2 * i), 2, p.externalDeg.begin());
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c) p.baseTcp.matrix()(r, c) = pose[12 * i + static_cast<size_t>(4 * r + c)];
    p.dexterity = dexterity[i];
    p.kukaStatus = status[i];
    p.kukaTurn = turn[i];
    p.reachable = reachable[i] != 0;
    p.collision = collision[i] != 0;
    if (configIndex[i] < 0 || static_cast<size_t>(configIndex[i]) >= configs.size() ||
        !configs[static_cast<size_t>(configIndex[i])].is_string())
      throw InputError(what + ": a configuration index is out of range", "the project file is damaged");
    p.fanucConfig = configs[static_cast<size_t>(configIndex[i])].get<std::string>();
  }
  return t;
}

nlohmann::json kinematicsToJson(const KinematicsResult& k)
{
  const size_t n = k.checks.size();
  std::vector<std::int32_t> reachable(n), collision(n);
  std::vector<double> dexterity(n), margin(n);
  for (size_t i = 0; i < n; ++i) {
    reachable[i] = k.checks[i].reachable ? 1 : 0;
    collision[i] = k.checks[i].collision ? 1 : 0;
    dexterity[i] = k.checks[i].dexterity;
    margin[i] = k.checks[i].limitMarginDeg;
  }
  return {{"joints", jointsToJson(k.joints)},
          {"path", trajectoryToJson(k.path)},
          {"axes", limitsToJson(k.axes)},
          {"checks",
           {{"count", n},
            {"reachable", codec::intsToBlob(reachable)},
            {"collision", codec::intsToBlob(collision)},
            {"dexterity", codec::doublesToBlob(dexterity)},
            {"limit_margin_deg", codec::doublesToBlob(margin)}}}};
}

KinematicsResult kinematicsFromJson(const nlohmann::json& j, const std::string& what)
{
  KinematicsResult k;
  k.joints = jointsFromJson(codec::field(j, "joints", what), what + " joints");
  k.path = trajectoryFromJson(codec::field(j, "path", what), what + " path");
  k.axes = limitsFromJson(codec::field(j, "axes", what), what + " axes");
  const auto& c = codec::field(j, "checks", what);
  const std::string cw = what + " checks";
  const std::int64_t count = codec::intField(c, "count", cw);
  if (count < 0) throw InputError(cw + ": negative point count", "the project file is damaged");
  const auto n = static_cast<size_t>(count);
  const auto reachable = sized(codec::blobToInts(codec::field(c, "reachable", cw), cw), n, cw);
  const auto collision = sized(codec::blobToInts(codec::field(c, "collision", cw), cw), n, cw);
  const auto dexterity = sized(codec::decodeDoubleBlob(codec::field(c, "dexterity", cw), cw), n, cw);
  const auto margin = sized(codec::decodeDoubleBlob(codec::field(c, "limit_margin_deg", cw), cw), n, cw);
  for (size_t i = 0; i < n; ++i)
    k.checks.push_back(KinematicsCheck{reachable[i] != 0, dexterity[i], margin[i], collision[i] != 0});
  return k;
}

template <class T, class F>
nlohmann::json orNull(const std::shared_ptr<const T>& p, F toJson)
{
  return p ? toJson(*p) : nlohmann::json(nullptr);
}

}  // namespace

nlohmann::json resultsToJson(const Results& r)
{
  nlohmann::json j;
  j["schema"] = kResultsSchema;
  j["field"] = orNull(r.field, [](const FieldResult& f) {
    return nlohmann::json{{"kind", f.kind}, {"source", f.source}, {"values", codec::doublesToBlob(f.values)}};
  });
  j["generatrices"] = orNull(r.generatrices, generatricesToJson);
  j["spiral"] = orNull(r.spiral, trajectoryToJson);
  j["process"] = orNull(r.process, trajectoryToJson);
  if (r.thermal) j["thermal"] = thermalResultToJson(*r.thermal);
  j["kinematics"] = orNull(r.kinematics, kinematicsToJson);
  // Payloads are wrapped so that a stored JSON null stays distinct from "not computed".
  const auto wrap = [](const nlohmann::json& p) { return nlohmann::json{{"payload", p}}; };
  j["export"] = r.exported ? wrap(reportToJson(*r.exported)) : nlohmann::json(nullptr);
  nlohmann::json reports = nlohmann::json::object();
  for (int i = 0; i < kStageCount; ++i)
    StageReports::visitMember(stageAt(i), [&](auto slot) {
      if (const auto& report = r.reports.*slot) reports[stageName(stageAt(i))] = wrap(reportToJson(*report));
    });
  j["reports"] = std::move(reports);
  return j;
}

Results resultsFromJson(const nlohmann::json& j)
{
  const std::string what = "project results";
  const int schema = codec::checkSchema(j, kResultsSchema, what);
  Results r;
  auto member = [&](const char* key) -> const nlohmann::json* {
    const auto& v = codec::field(j, key, what);
    return v.is_null() ? nullptr : &v;
  };
  const auto payload = [&](const nlohmann::json& v, const std::string& name) -> const nlohmann::json& {
    return codec::field(v, "payload", what + " " + name);
  };
  const auto read = [&](const nlohmann::json& v, const std::string& name, auto& slot) {
    using Report = std::remove_const_t<typename std::decay_t<decltype(slot)>::element_type>;
    slot = std::make_shared<const Report>(
        reportFromJson<Report>(payload(v, name), what + " " + name, "the project file is damaged"));
  };
  if (const auto* f = member("field")) {
    FieldResult fr;
    fr.kind = codec::stringField(*f, "kind", what + " field");
    fr.source = codec::stringField(*f, "source", what + " field");
    fr.values = codec::decodeDoubleBlob(codec::field(*f, "values", what + " field"), what + " field values");
    r.field = std::make_shared<const FieldResult>(std::move(fr));
  }
  if (const auto* g = member("generatrices"))
    r.generatrices = std::make_shared<const Generatrices>(generatricesFromJson(*g, what + " generatrices"));
  if (const auto* t = member("spiral"))
    r.spiral = std::make_shared<const Trajectory>(trajectoryFromJson(*t, what + " spiral"));
  if (const auto* t = member("process"))
    r.process = std::make_shared<const Trajectory>(trajectoryFromJson(*t, what + " process"));
  if (j.contains("thermal") && !j["thermal"].is_null())
    r.thermal =
        std::make_shared<const ThermalStageResult>(thermalResultFromJson(j["thermal"], what + " thermal"));
  if (const auto* k = member("kinematics"); k && schema >= 2)
    r.kinematics = std::make_shared<const KinematicsResult>(kinematicsFromJson(*k, what + " kinematics"));
  if (const auto* e = member("export")) read(*e, "export", r.exported);
  const auto& reports = codec::field(j, "reports", what);
  if (!reports.is_object())
    throw InputError(what + ": 'reports' is not an object", "the project file is damaged");
  for (auto it = reports.begin(); it != reports.end(); ++it) {
    const auto stage = parseStageName(it.key());
    // A report of a stage this version does not know is dropped: reports are informative only.
    if (!stage) continue;
    StageReports::visitMember(*stage,
                              [&](auto slot) { read(it.value(), it.key() + " report", r.reports.*slot); });
  }
  return r;
}

}  // namespace spira
