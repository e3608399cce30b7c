#include "gcode_machine.h"

#include <cctype>
#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"
#include "spira/base/number_text.h"
#include "spira/io/json_read.h"

namespace spira {

namespace {

constexpr const char* kFormatHint =
    "fix the machine file (its format is described in docs/machine-format.md)";
constexpr std::array<const char*, 3> kWorldAxes = {"X", "Y", "Z"};

class MachineReader {
 public:
  explicit MachineReader(std::string what) : what_(std::move(what)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem,
                         const std::string& hint = kFormatHint) const
  {
    throw InputError(what_ + ": " + where + ": " + problem, hint);
  }

  const nlohmann::json& need(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    if (!j.is_object() || !j.contains(key)) fail(where, std::string("'") + key + "' is missing");
    return j.at(key);
  }

  std::string text(const nlohmann::json& j, const char* key, const std::string& where,
                   const std::string& fallback) const
  {
    if (!j.is_object() || !j.contains(key)) return fallback;
    const auto& v = j.at(key);
    if (!v.is_string())
      fail(where, std::string("'") + key + "' must be a string, not " + json_read::describe(v));
    return v.get<std::string>();
  }

  double number(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    const auto& v = need(j, key, where);
    if (!v.is_number() || !std::isfinite(v.get<double>()))
      fail(where, std::string("'") + key + "' must be a finite number, not " + json_read::describe(v));
    return v.get<double>();
  }

  double number(const nlohmann::json& j, const char* key, const std::string& where, double fallback) const
  {
    return j.is_object() && j.contains(key) ? number(j, key, where) : fallback;
  }

  Vec3 triple(const nlohmann::json& j, const char* key, const std::string& where, const Vec3& fallback) const
  {
    if (!j.is_object() || !j.contains(key)) return fallback;
    const auto& v = j.at(key);
    if (!v.is_array() || v.size() != 3) fail(where, std::string("'") + key + "' must be 3 numbers [x, y, z]");
    Vec3 out;
    for (int i = 0; i < 3; ++i) {
      if (!v[i].is_number() || !std::isfinite(v[i].get<double>()))
        fail(where, std::string("'") + key + "' must be 3 finite numbers [x, y, z]");
      out[i] = v[i].get<double>();
    }
    return out;
  }

  // "X", "Y", "Z" or a direction [x, y, z]; returned as a unit vector.
  Vec3 direction(const nlohmann::json& j, const char* key, const std::string& where) const
  {
    const auto& v = need(j, key, where);
    Vec3 d;
    if (v.is_string()) {
      const std::string s = v.get<std::string>();
      if (s == "X") return Vec3::UnitX();
      if (s == "Y") return Vec3::UnitY();
      if (s == "Z") return Vec3::UnitZ();
      fail(where, std::string("'") + key + "' is \"" + s + "\"",
           "write \"X\", \"Y\", \"Z\" or a direction [x, y, z]");
    }
    d = triple(j, key, where, Vec3::Zero());
    if (d.norm() < 1e-9)
      fail(where, std::string("'") + key + "' is a zero vector",
           "give the direction the axis turns about, e.g. [0, 0, 1]");
    return d.normalized();
  }

  void limits(const nlohmann::json& j, const char* minKey, const char* maxKey, const std::string& where,
              double& lo, double& hi) const
  {
    lo = number(j, minKey, where);
    hi = number(j, maxKey, where);
    if (!(lo < hi))
      fail(where,
           std::string(minKey) + " " + roundedText(lo, 3) + " is not below " + maxKey + " " +
               roundedText(hi, 3),
           "give the axis a range with " + std::string(minKey) + " < " + maxKey);
  }

  const std::string& what() const { return what_; }

 private:
  std::string what_;
};

bool isRotaryLetter(const std::string& s)
{
  return s == "A" || s == "B" || s == "C";
}

void checkTemplate(const MachineReader& r, const std::string& text, const char* key, const char* field)
{
  if (text.empty())
    r.fail("process", std::string("'") + key + "' is empty",
           "write the line the controller runs, e.g. \"M3\"");
  if (field && text.find(field) == std::string::npos)
    r.fail("process", std::string("'") + key + "' \"" + text + "\" has no " + field,
           std::string("put ") + field + " where the number goes, e.g. \"S" + field + "\"");
  if (text.find('\n') != std::string::npos || text.find('\r') != std::string::npos)
    r.fail("process", std::string("'") + key + "' holds a line break",
           "write one line; two commands can share it");
}

}  // namespace

GcodeMachine machineFromText(const std::string& text, const std::string& what)
{
  const MachineReader r(what);
  const nlohmann::json j =
      json_read::parse(text, what, "fix the syntax (docs/machine-format.md shows the format)");
  if (!j.is_object()) r.fail("top level", "the file must hold one JSON object");
  const auto& version = r.need(j, "spira_machine", "top level");
  if (!version.is_number_integer() || version.get<long long>() != 1)
    r.fail("top level", "spira_machine " + json_read::describe(version) +
                            " is not supported (this Spira reads version 1)");
  GcodeMachine m;
  m.name = r.text(j, "name", "top level", "");

  std::set<std::string> letters;
  auto useLetter = [&](const std::string& letter, const std::string& where) {
    if (letter.size() != 1 || !std::isupper(static_cast<unsigned char>(letter[0])))
      r.fail(where, "letter \"" + letter + "\" is not one capital letter", "write the axis word, e.g. \"X\"");
    if (!letters.insert(letter).second)
      r.fail(where, "letter " + letter + " is used by two axes", "give every axis its own letter");
  };

  const auto& linear = r.need(j, "linear_axes", "top level");
  if (!linear.is_array() || linear.size() != 3)
    r.fail("linear_axes", "must list 3 axes, along the machine's X, Y and Z");
  for (size_t i = 0; i < 3; ++i) {
    const std::string where = std::string("linear_axes[") + std::to_string(i) + "] (" + kWorldAxes[i] + ")";
    LinearAxis& a = m.linear[i];
    a.letter = r.text(linear[i], "letter", where, kWorldAxes[i]);
    useLetter(a.letter, where);
    r.limits(linear[i], "min_mm", "max_mm", where, a.minMm, a.maxMm);
  }

  const auto& rotary = r.need(j, "rotary_axes", "top level");
  if (!rotary.is_array() || rotary.size() != 2)
    r.fail("rotary_axes", "must list 2 axes: the one the gantry carries, then the one it carries");
  for (size_t i = 0; i < 2; ++i) {
    const std::string where = "rotary_axes[" + std::to_string(i) + "]";
    RotaryAxis& a = m.rotary[i];
    a.letter = r.text(rotary[i], "letter", where, "");
    if (!isRotaryLetter(a.letter))
      r.fail(where, "letter \"" + a.letter + "\" is not a rotary axis", "write A, B or C");
    useLetter(a.letter, where + " (" + a.letter + ")");
    a.about = r.direction(rotary[i], "about", where + " (" + a.letter + ")");
    r.limits(rotary[i], "min_deg", "max_deg", where + " (" + a.letter + ")", a.minDeg, a.maxDeg);
  }
  if (m.rotary[0].about.cross(m.rotary[1].about).norm() < 1e-6)
    r.fail("rotary_axes",
           m.rotary[0].letter + " and " + m.rotary[1].letter +
               " turn about parallel axes, so the head cannot point the torch in two directions",
           "make the second axis turn about a direction across the first, e.g. C about Z and A about X");

  m.firstToSecond = r.triple(j, "first_to_second_mm", "top level", m.firstToSecond);
  m.secondToTip = r.triple(j, "second_to_tip_mm", "top level", m.secondToTip);
  const Vec3 tool = r.triple(j, "tool_direction", "top level", m.toolDirection);
  if (tool.norm() < 1e-9)
    r.fail("tool_direction", "is a zero vector",
           "give the torch axis towards the deposit at zero angles, e.g. [0, 0, -1]");
  m.toolDirection = tool.normalized();
  if (m.toolDirection.cross(m.rotary[1].about).norm() < 1e-6)
    r.fail("tool_direction",
           "lies along the second rotary axis " + m.rotary[1].letter +
               ", which would only spin the torch about itself",
           "list the tilting axis second (e.g. C about Z first, then A about X)");
  m.partOrigin = r.triple(j, "part_origin_mm", "top level", m.partOrigin);

  const nlohmann::json empty = nlohmann::json::object();
  const auto& feed = j.contains("feed") ? j.at("feed") : empty;
  const std::string unit = r.text(feed, "unit", "feed", "mm/min");
  if (unit != "mm/min") r.fail("feed", "unit \"" + unit + "\" is not supported", "write \"mm/min\" (G94)");
  m.maxFeed = r.number(feed, "max_mm_per_min", "feed", m.maxFeed);
  if (!(m.maxFeed > 0.0))
    r.fail("feed", "max_mm_per_min must be above 0", "give the machine's largest G1 feed");

  const auto& process = j.contains("process") ? j.at("process") : empty;
  m.arcOn = r.text(process, "arc_on", "process", m.arcOn);
  m.arcOff = r.text(process, "arc_off", "process", m.arcOff);
  m.wireFeed = r.text(process, "wire_feed", "process", m.wireFeed);
  m.wireFeedUnit = r.text(process, "wire_feed_unit", "process", m.wireFeedUnit);
  m.dwell = r.text(process, "dwell", "process", m.dwell);
  m.programEnd = r.text(process, "program_end", "process", m.programEnd);
  checkTemplate(r, m.arcOn, "arc_on", nullptr);
  checkTemplate(r, m.arcOff, "arc_off", nullptr);
  checkTemplate(r, m.wireFeed, "wire_feed", "{wfs}");
  checkTemplate(r, m.dwell, "dwell", "{s}");
  checkTemplate(r, m.programEnd, "program_end", nullptr);
  if (m.wireFeedUnit != "mm/min" && m.wireFeedUnit != "m/min" && m.wireFeedUnit != "mm/s")
    r.fail("process", "wire_feed_unit \"" + m.wireFeedUnit + "\" is not known",
           "write \"mm/min\", \"m/min\" or \"mm/s\"");
  return m;
}

GcodeMachine readMachineFile(const std::filesystem::path& file)
{
  return machineFromText(readFile(file), "machine file " + file.string());
}

}  // namespace spira
