#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/document/json_codec.h"
#include "spira/document/results.h"

namespace spira {

namespace {

constexpr int kResultsSchema = 1;

// The codecs below list every member of these types. When a member is added, these fail to
// compile as a reminder to store it too (and to bump kResultsSchema if old files lack it).
static_assert(sizeof(void*) != 8 || sizeof(TrajectoryPoint) == 144, "update trajectoryToJson/FromJson");
static_assert(sizeof(void*) != 8 || sizeof(Generatrices) == 80, "update generatricesToJson/FromJson");

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

template <class T>
std::vector<T> sized(std::vector<T> v, size_t n, const std::string& what)
{
  if (v.size() != n)
    throw InputError(what + ": " + std::to_string(v.size()) + " values for " + std::to_string(n) + " points",
                     "the project file is damaged");
  return v;
}

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

nlohmann::json generatricesToJson(const Generatrices& g)
{
  nlohmann::json lines = nlohmann::json::array();
  for (const Polyline& l : g.lines) lines.push_back(codec::vec3sToBlob(l));
  nlohmann::json normals = nlohmann::json::array();
  for (const auto& n : g.normals) normals.push_back(codec::vec3sToBlob(n));
  return {{"lines", std::move(lines)},
          {"normals", std::move(normals)},
          {"has_closure_point", g.hasClosurePoint},
          {"closure_point", codec::vec3sToBlob({g.closurePoint})}};
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
  return g;
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
  // Payloads are wrapped so that a stored JSON null stays distinct from "not computed".
  const auto wrap = [](const nlohmann::json& p) { return nlohmann::json{{"payload", p}}; };
  j["kinematics"] = orNull(r.kinematics, wrap);
  j["export"] = orNull(r.exported, wrap);
  nlohmann::json reports = nlohmann::json::object();
  for (int i = 0; i < kStageCount; ++i)
    if (r.reports[i]) reports[stageName(stageAt(i))] = wrap(*r.reports[i]);
  j["reports"] = std::move(reports);
  return j;
}

Results resultsFromJson(const nlohmann::json& j)
{
  const std::string what = "project results";
  codec::checkSchema(j, kResultsSchema, what);
  Results r;
  auto member = [&](const char* key) -> const nlohmann::json* {
    const auto& v = codec::field(j, key, what);
    return v.is_null() ? nullptr : &v;
  };
  const auto payload = [&](const nlohmann::json& v, const std::string& name) {
    return std::make_shared<const nlohmann::json>(codec::field(v, "payload", what + " " + name));
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
  if (const auto* k = member("kinematics")) r.kinematics = payload(*k, "kinematics");
  if (const auto* e = member("export")) r.exported = payload(*e, "export");
  const auto& reports = codec::field(j, "reports", what);
  if (!reports.is_object())
    throw InputError(what + ": 'reports' is not an object", "the project file is damaged");
  for (auto it = reports.begin(); it != reports.end(); ++it) {
    const auto stage = parseStageName(it.key());
    // A report of a stage this version does not know is dropped: reports are informative only.
    if (stage) r.reports[stageIndex(*stage)] = payload(it.value(), it.key() + " report");
  }
  return r;
}

}  // namespace spira
