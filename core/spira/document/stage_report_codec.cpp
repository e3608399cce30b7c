#include "spira/document/stage_report_codec.h"

#include <cmath>
#include <limits>

#include <nlohmann/json.hpp>

#include "spira/base/error.h"
#include "spira/io/json_read.h"

namespace spira {
namespace {

using nlohmann::json;

// Where a value sits, for a message: the report (`what`) and the key path inside it.
struct Where {
  const std::string& what;
  const std::string& hint;
  std::string path;

  Where at(const std::string& key) const { return {what, hint, path.empty() ? key : path + "." + key}; }
  Where item(size_t i) const { return {what, hint, path + "[" + std::to_string(i) + "]"}; }
  [[noreturn]] void fail(const char* expected, const json& found) const
  {
    throw InputError(
        what + ": field '" + path + "' must be " + expected + ", found " + json_read::describe(found), hint);
  }
};

json encode(bool v);
json encode(std::int64_t v);
json encode(double v);
json encode(const std::string& v);
json encode(const Vec3& v);
json encode(const std::array<double, 2>& v);
json encode(const SlowedPointRecord& v);
template <class T>
json encode(const std::vector<T>& v);
template <class T>
json encode(const std::map<std::string, T>& v);
template <class Record>
json encode(const Record& r);

void decode(const json& v, bool& out, const Where& w);
void decode(const json& v, std::int64_t& out, const Where& w);
void decode(const json& v, double& out, const Where& w);
void decode(const json& v, std::string& out, const Where& w);
void decode(const json& v, Vec3& out, const Where& w);
void decode(const json& v, std::array<double, 2>& out, const Where& w);
void decode(const json& v, SlowedPointRecord& out, const Where& w);
template <class T>
void decode(const json& v, std::vector<T>& out, const Where& w);
template <class T>
void decode(const json& v, std::map<std::string, T>& out, const Where& w);
template <class Record>
void decode(const json& v, Record& out, const Where& w);

class Writer {
 public:
  explicit Writer(json& j) : j_(j) {}
  template <class T>
  void operator()(const char* key, const T& v)
  {
    j_[key] = encode(v);
  }
  template <class T>
  void optional(const char* key, const std::optional<T>& v)
  {
    if (v) j_[key] = encode(*v);
  }
  template <class T>
  void nullable(const char* key, const std::optional<T>& v)
  {
    j_[key] = v ? encode(*v) : json(nullptr);
  }

 private:
  json& j_;
};

class Reader {
 public:
  Reader(const json& j, const Where& where) : j_(j), where_(where) {}
  template <class T>
  void operator()(const char* key, T& v)
  {
    if (const json* m = find(key)) decode(*m, v, where_.at(key));
  }
  template <class T>
  void optional(const char* key, std::optional<T>& v)
  {
    v.reset();
    if (const json* m = find(key); m && !m->is_null()) decode(*m, v.emplace(), where_.at(key));
  }
  template <class T>
  void nullable(const char* key, std::optional<T>& v)
  {
    optional(key, v);
  }

 private:
  const json* find(const char* key) const
  {
    const auto it = j_.find(key);
    return it == j_.end() ? nullptr : &*it;
  }
  const json& j_;
  const Where& where_;
};

json encode(bool v)
{
  return v;
}
json encode(std::int64_t v)
{
  return v;
}
json encode(double v)
{
  return v;  // dumped as null when not finite
}
json encode(const std::string& v)
{
  return v;
}
json encode(const Vec3& v)
{
  return json::array({v.x(), v.y(), v.z()});
}
json encode(const std::array<double, 2>& v)
{
  return json::array({v[0], v[1]});
}
json encode(const SlowedPointRecord& p)
{
  return json::array({p.point, p.factor, p.height, p.slowedHeight, p.fits});
}
template <class T>
json encode(const std::vector<T>& v)
{
  json a = json::array();
  for (const T& x : v) a.push_back(encode(x));
  return a;
}
template <class T>
json encode(const std::map<std::string, T>& v)
{
  json o = json::object();
  for (const auto& [key, x] : v) o[key] = encode(x);
  return o;
}
template <class Record>
json encode(const Record& r)
{
  json j = json::object();
  Writer writer(j);
  Record::fields(r, writer);
  return j;
}

void decode(const json& v, bool& out, const Where& w)
{
  if (!v.is_boolean()) w.fail("true or false", v);
  out = v.get<bool>();
}
void decode(const json& v, std::int64_t& out, const Where& w)
{
  if (v.is_number_integer()) {
    if (v.is_number_unsigned() &&
        v.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<std::int64_t>::max()))
      w.fail("a whole number", v);
    out = v.get<std::int64_t>();
    return;
  }
  const double d = v.is_number_float() ? v.get<double>() : 0.5;
  if (!v.is_number_float() || d != std::floor(d) || std::abs(d) > 9.2e18) w.fail("a whole number", v);
  out = static_cast<std::int64_t>(d);
}
void decode(const json& v, double& out, const Where& w)
{
  if (v.is_null())
    out = std::numeric_limits<double>::quiet_NaN();
  else if (v.is_number())
    out = v.get<double>();
  else
    w.fail("a number", v);
}
void decode(const json& v, std::string& out, const Where& w)
{
  if (!v.is_string()) w.fail("a string", v);
  out = v.get<std::string>();
}
template <size_t N>
void numbers(const json& v, double* out, const Where& w, const char* expected)
{
  if (!v.is_array() || v.size() != N) w.fail(expected, v);
  for (size_t k = 0; k < N; ++k) decode(v[k], out[k], w.item(k));
}
void decode(const json& v, Vec3& out, const Where& w)
{
  numbers<3>(v, out.data(), w, "an array of 3 numbers");
}
void decode(const json& v, std::array<double, 2>& out, const Where& w)
{
  numbers<2>(v, out.data(), w, "an array of 2 numbers");
}
void decode(const json& v, SlowedPointRecord& p, const Where& w)
{
  if (!v.is_array() || v.size() != 5) w.fail("[index, factor, height_mm, slowed_height_mm, fits]", v);
  decode(v[0], p.point, w.item(0));
  decode(v[1], p.factor, w.item(1));
  decode(v[2], p.height, w.item(2));
  decode(v[3], p.slowedHeight, w.item(3));
  decode(v[4], p.fits, w.item(4));
}
template <class T>
void decode(const json& v, std::vector<T>& out, const Where& w)
{
  if (!v.is_array()) w.fail("an array", v);
  out.assign(v.size(), T{});
  for (size_t i = 0; i < v.size(); ++i) decode(v[i], out[i], w.item(i));
}
template <class T>
void decode(const json& v, std::map<std::string, T>& out, const Where& w)
{
  if (!v.is_object()) w.fail("an object", v);
  out.clear();
  for (auto it = v.begin(); it != v.end(); ++it) decode(it.value(), out[it.key()], w.at(it.key()));
}
template <class Record>
void decode(const json& v, Record& out, const Where& w)
{
  if (!v.is_object()) w.fail("an object", v);
  Reader reader(v, w);
  Record::fields(out, reader);
}

}  // namespace

template <class Report>
nlohmann::json reportToJson(const Report& report)
{
  return encode(report);
}

template <class Report>
Report reportFromJson(const nlohmann::json& j, const std::string& what, const std::string& hint)
{
  Report r;
  const Where where{what, hint, ""};
  if (!j.is_object())
    throw InputError(what + ": expected a JSON object, found " + json_read::describe(j), hint);
  Reader reader(j, where);
  Report::fields(r, reader);
  return r;
}

template <class Report>
bool sameReport(const Report& a, const Report& b)
{
  return encode(a).dump() == encode(b).dump();
}

#define SPIRA_STAGE_REPORT(Report)                                                                       \
  template nlohmann::json reportToJson<Report>(const Report&);                                           \
  template Report reportFromJson<Report>(const nlohmann::json&, const std::string&, const std::string&); \
  template bool sameReport<Report>(const Report&, const Report&);

SPIRA_STAGE_REPORT(FieldStageReport)
SPIRA_STAGE_REPORT(GeneratricesStageReport)
SPIRA_STAGE_REPORT(SpiralStageReport)
SPIRA_STAGE_REPORT(ProcessStageReport)
SPIRA_STAGE_REPORT(ThermalStageReport)
SPIRA_STAGE_REPORT(MotionStageReport)
SPIRA_STAGE_REPORT(KinematicsStageReport)
SPIRA_STAGE_REPORT(ExportStageResult)
SPIRA_STAGE_REPORT(DepositCheckRecord)

#undef SPIRA_STAGE_REPORT

}  // namespace spira
