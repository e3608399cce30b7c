#include "architecture/layering_check.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <iterator>
#include <optional>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace spira::layering {

namespace fs = std::filesystem;

namespace {

struct Include {
  int line = 0;
  std::string header;
  bool angled = false;
};

std::vector<Include> includesOf(const fs::path& file)
{
  static const std::regex pattern(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
  std::ifstream in(file);
  std::vector<Include> out;
  std::string text;
  int line = 0;
  std::smatch m;
  while (std::getline(in, text)) {
    ++line;
    if (text.find("include") != std::string::npos && std::regex_search(text, m, pattern))
      out.push_back({line, m[2].str(), m[1].str() == "<"});
  }
  return out;
}

std::vector<fs::path> sourcesUnder(const fs::path& dir)
{
  std::vector<fs::path> files;
  if (!fs::is_directory(dir)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".h" || ext == ".hpp" || ext == ".cpp")) files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

bool startsWith(const std::string& s, const std::string& prefix)
{
  return s.compare(0, prefix.size(), prefix) == 0;
}

bool isQtOrVtk(const std::string& header)
{
  return startsWith(header, "vtk") || startsWith(header, "QVTK") || startsWith(header, "Qt") ||
         (header.size() > 1 && header[0] == 'Q' && std::isupper(static_cast<unsigned char>(header[1])));
}

// The CMake target a third-party header belongs to; empty for the standard and system headers.
std::string libraryOf(const std::string& header)
{
  static const std::vector<std::pair<std::string, std::string>> prefixes = {
      {"Eigen/", "Eigen3::Eigen"},   {"nlohmann/", "nlohmann_json::nlohmann_json"},
      {"tbb/", "TBB::tbb"},          {"CGAL/", "CGAL::CGAL"},
      {"cholmod", "Spira::cholmod"}, {"pcl/", "Spira::pcl"},
      {"urdf_", "Spira::urdfdom"},   {"console_bridge/", "Spira::urdfdom"},
      {"tinyxml", "Spira::urdfdom"}};
  for (const auto& [prefix, library] : prefixes)
    if (startsWith(header, prefix)) return library;
  return {};
}

// The core area of "spira/<area>/...", if the header is one.
std::optional<std::string> coreAreaOf(const std::string& header)
{
  if (!startsWith(header, "spira/")) return std::nullopt;
  const size_t slash = header.find('/', 6);
  if (slash == std::string::npos) return std::nullopt;
  return header.substr(6, slash - 6);
}

std::set<std::string> pluginNames(const fs::path& root)
{
  std::set<std::string> names;
  if (!fs::is_directory(root / "plugins")) return names;
  for (const auto& e : fs::directory_iterator(root / "plugins"))
    if (e.is_directory() && fs::exists(e.path() / "CMakeLists.txt"))
      names.insert(e.path().filename().string());
  return names;
}

// The plugin a header names ("<plugin>/..." or a path through "plugins/<plugin>/"), if any.
std::optional<std::string> pluginOf(const std::string& header, const std::set<std::string>& plugins)
{
  std::string h = header;
  while (startsWith(h, "../")) h = h.substr(3);
  if (startsWith(h, "plugins/")) h = h.substr(8);
  const size_t slash = h.find('/');
  if (slash == std::string::npos) return std::nullopt;
  const std::string first = h.substr(0, slash);
  if (plugins.count(first)) return first;
  return std::nullopt;
}

bool isPluginRegistryHeader(const std::string& header)
{
  return fs::path(header).filename() == "builtin_plugins.h";
}

// The words of the first call `name(...)` in a CMake file, comments dropped, and its line.
std::pair<int, std::vector<std::string>> firstCall(const fs::path& cmakeLists, const std::string& name)
{
  std::ifstream in(cmakeLists);
  if (!in) throw std::runtime_error("cannot read " + cmakeLists.string());
  std::string text;
  int line = 0, first = 0;
  std::string call;
  bool inside = false;
  while (std::getline(in, text)) {
    ++line;
    text = text.substr(0, text.find('#'));
    if (!inside) {
      const size_t start = text.find(name + "(");
      if (start == std::string::npos) continue;
      inside = true;
      first = line;
      text = text.substr(start + name.size() + 1);
    }
    const size_t close = text.find(')');
    call += " " + text.substr(0, close);
    if (close != std::string::npos) break;
  }
  if (!inside) throw std::runtime_error(cmakeLists.string() + " has no " + name + "() call");
  std::istringstream words(call);
  std::vector<std::string> out;
  for (std::string word; words >> word;) out.push_back(word);
  return {first, out};
}

// A quoted include resolved as the compiler would: next to the including file first.
std::optional<fs::path> besideFile(const fs::path& file, const Include& inc)
{
  if (inc.angled) return std::nullopt;
  const fs::path beside = (file.parent_path() / inc.header).lexically_normal();
  if (fs::exists(beside)) return beside;
  return std::nullopt;
}

bool isUnder(const fs::path& path, const fs::path& dir)
{
  const fs::path rel = path.lexically_relative(dir);
  return !rel.empty() && *rel.begin() != "..";
}

class Checker {
 public:
  // The root is normalised so that the paths includes resolve to compare with the ones listed.
  explicit Checker(const fs::path& root)
      : root_((fs::absolute(root) / "").lexically_normal().parent_path()), plugins_(pluginNames(root_))
  {
    for (const std::string& p : plugins_)
      declarations_[p] = readPluginDeclaration(root_ / "plugins" / p / "CMakeLists.txt");
  }

  std::vector<Violation> run()
  {
    checkCore();
    checkUi();
    checkPlugins();
    checkPluginClients();
    checkExamplePlugins();
    return std::move(out_);
  }

 private:
  void report(const fs::path& file, int line, std::string what)
  {
    out_.push_back({fs::relative(file, root_).generic_string(), line, std::move(what)});
  }

  void checkCore()
  {
    const fs::path cmake = root_ / "core" / "CMakeLists.txt";
    const auto areas = readCoreAreas(cmake);
    checkAcyclic(cmake, areas);
    for (const auto& e : fs::directory_iterator(root_ / "core" / "spira")) {
      if (!e.is_directory()) continue;
      const std::string area = e.path().filename().string();
      const auto it = areas.find(area);
      if (it == areas.end()) {
        report(cmake, 1, "core/spira/" + area + " has no spira_core_area(" + area + " DEPS ...)");
        continue;
      }
      checkCoreArea(area, it->second, e.path(), cmake);
    }
  }

  void checkCoreArea(const std::string& area, const CoreArea& rules, const fs::path& dir,
                     const fs::path& cmake)
  {
    std::set<std::string> usedAreas, usedLibraries;
    for (const fs::path& file : sourcesUnder(dir))
      for (const Include& inc : includesOf(file)) {
        const std::string& h = inc.header;
        if (isQtOrVtk(h)) {
          report(file, inc.line, "core includes " + h + ": the core never uses Qt or VTK");
        } else if (startsWith(h, "spira/ui/") || isPluginRegistryHeader(h) || pluginOf(h, plugins_)) {
          report(file, inc.line, "core includes " + h + ": the core never includes ui, app or plugin files");
        } else if (const auto other = coreAreaOf(h)) {
          if (*other == area) continue;
          usedAreas.insert(*other);
          if (!rules.areas.count(*other))
            report(file, inc.line,
                   "area " + area + " includes " + h + " but core/CMakeLists.txt does not list spira_" +
                       *other + " in its DEPS");
        } else if (inc.angled) {
          const std::string library = libraryOf(h);
          if (library.empty()) continue;
          usedLibraries.insert(library);
          if (!rules.libraries.count(library))
            report(file, inc.line,
                   "area " + area + " includes " + h + " but core/CMakeLists.txt does not list " + library +
                       " in its DEPS");
        }
      }
    for (const std::string& dep : rules.areas)
      if (!usedAreas.count(dep))
        report(cmake, rules.line,
               "area " + area + " lists spira_" + dep + " but includes none of its headers");
    for (const std::string& library : rules.libraries)
      if (!usedLibraries.count(library))
        report(cmake, rules.line, "area " + area + " lists " + library + " but includes none of its headers");
  }

  void checkAcyclic(const fs::path& cmake, const std::map<std::string, CoreArea>& areas)
  {
    std::map<std::string, int> state;  // 1: on the current path, 2: done
    std::vector<std::string> path;
    std::function<void(const std::string&)> visit = [&](const std::string& a) {
      state[a] = 1;
      path.push_back(a);
      const auto it = areas.find(a);
      if (it != areas.end())
        for (const std::string& b : it->second.areas) {
          if (state[b] == 1) {
            std::string cycle;
            for (auto p = std::find(path.begin(), path.end(), b); p != path.end(); ++p) cycle += *p + " -> ";
            report(cmake, it->second.line, "the DEPS form a cycle: " + cycle + b);
          } else if (state[b] == 0) {
            visit(b);
          }
        }
      path.pop_back();
      state[a] = 2;
    };
    for (const auto& [name, area] : areas)
      if (state[name] == 0) visit(name);
  }

  void checkUi()
  {
    for (const fs::path& file : sourcesUnder(root_ / "ui"))
      for (const Include& inc : includesOf(file))
        if (isPluginRegistryHeader(inc.header) || pluginOf(inc.header, plugins_))
          report(file, inc.line,
                 "ui includes " + inc.header +
                     ": the ui never includes plugin files (app/ passes the registry in)");
  }

  // The plugin and the header inside its folder that an include names, if it names one: a quoted
  // include next to the file, or "<plugin>/..." through the plugins folder.
  std::optional<std::pair<std::string, std::string>> pluginHeaderOf(const fs::path& file,
                                                                    const Include& inc) const
  {
    if (const auto beside = besideFile(file, inc)) {
      const fs::path rel = beside->lexically_relative(root_ / "plugins");
      if (rel.empty() || *rel.begin() == ".." || std::distance(rel.begin(), rel.end()) < 2)
        return std::nullopt;
      const std::string plugin = rel.begin()->string();
      const fs::path inside = rel.lexically_relative(plugin);
      if (!plugins_.count(plugin) || *inside.begin() == "tests") return std::nullopt;
      return std::make_pair(plugin, inside.generic_string());
    }
    const auto plugin = pluginOf(inc.header, plugins_);
    if (!plugin) return std::nullopt;
    return std::make_pair(*plugin, inc.header.substr(inc.header.find(*plugin + "/") + plugin->size() + 1));
  }

  void checkPlugins()
  {
    const fs::path coreCMake = root_ / "core" / "CMakeLists.txt";
    const std::set<std::string> sdk = readSdkAreas(coreCMake);
    for (const std::string& plugin : plugins_) {
      const fs::path dir = root_ / "plugins" / plugin;
      const PluginDeclaration& declared = declarations_.at(plugin);
      std::set<std::string> usedAreas;
      for (const fs::path& file : sourcesUnder(dir)) {
        const bool test = isUnder(file, dir / "tests");
        for (const Include& inc : includesOf(file)) {
          const auto header = pluginHeaderOf(file, inc);
          if (header && header->first != plugin) {
            report(file, inc.line,
                   "plugin " + plugin + " includes " + inc.header + " of plugin " + header->first +
                       ": plugins reach each other only through the registry");
          } else if (header && test && !declared.publicHeaders.count(header->second)) {
            report(file, inc.line,
                   "the tests of plugin " + plugin + " include " + inc.header + ", which is not one of its " +
                       "PUBLIC_HEADERS");
          } else if (startsWith(inc.header, "spira/ui/")) {
            report(file, inc.line,
                   "plugin " + plugin + " includes " + inc.header + ": plugins never use the ui");
          } else if (const auto area = coreAreaOf(inc.header); area && !test) {
            usedAreas.insert(*area);
            if (!sdk.count(*area) && !declared.areas.count(*area))
              report(file, inc.line,
                     "plugin " + plugin + " includes " + inc.header +
                         " but neither spira_sdk nor its AREAS " + "list " + *area);
          }
        }
      }
      const fs::path cmake = dir / "CMakeLists.txt";
      for (const std::string& area : declared.areas) {
        if (sdk.count(area))
          report(cmake, declared.line,
                 "plugin " + plugin + " lists " + area + " in AREAS, which spira_sdk brings");
        else if (!usedAreas.count(area))
          report(cmake, declared.line,
                 "plugin " + plugin + " lists " + area + " in AREAS but includes none of its headers");
      }
    }
  }

  // Code outside the plugins (ui and core are held to "no plugin at all" above) uses their
  // public headers only.
  void checkPluginClients()
  {
    for (const char* top : {"tests", "bench", "app", "python", "examples", "fuzz"})
      for (const fs::path& file : sourcesUnder(root_ / top)) {
        if (isUnder(file, root_ / "tests" / "architecture" / "fixtures")) continue;
        for (const Include& inc : includesOf(file)) {
          const auto header = pluginHeaderOf(file, inc);
          if (header && !declarations_.at(header->first).publicHeaders.count(header->second))
            report(file, inc.line,
                   "includes " + inc.header + " of plugin " + header->first + ", which is not one of its " +
                       "PUBLIC_HEADERS");
        }
      }
  }

  // The worked example is what a third party builds against the SDK alone.
  void checkExamplePlugins()
  {
    const std::set<std::string> sdk = readSdkAreas(root_ / "core" / "CMakeLists.txt");
    for (const fs::path& file : sourcesUnder(root_ / "examples" / "plugin_sdk")) {
      const std::string name = file.filename().string();
      if (name.size() > 9 && name.compare(name.size() - 9, 9, "_test.cpp") == 0) continue;
      for (const Include& inc : includesOf(file))
        if (const auto area = coreAreaOf(inc.header); area && !sdk.count(*area))
          report(file, inc.line,
                 "the example plugins include " + inc.header + ", which spira_sdk does not bring");
    }
  }

  fs::path root_;
  std::set<std::string> plugins_;
  std::map<std::string, PluginDeclaration> declarations_;
  std::vector<Violation> out_;
};

}  // namespace

std::string describe(const Violation& v)
{
  return v.file + ":" + std::to_string(v.line) + ": " + v.what;
}

std::map<std::string, CoreArea> readCoreAreas(const fs::path& cmakeLists)
{
  std::ifstream in(cmakeLists);
  if (!in) throw std::runtime_error("cannot read " + cmakeLists.string());
  std::map<std::string, CoreArea> areas;
  std::string text;
  int line = 0;
  while (std::getline(in, text)) {
    ++line;
    const size_t start = text.find("spira_core_area(");
    if (start != 0) continue;
    const int first = line;
    std::string call = text.substr(start + 16);
    while (call.find(')') == std::string::npos && std::getline(in, text)) {
      ++line;
      call += " " + text;
    }
    std::istringstream words(call.substr(0, call.find(')')));
    std::string name, word;
    words >> name;
    CoreArea area;
    area.line = first;
    while (words >> word) {
      if (word == "DEPS") continue;
      if (startsWith(word, "spira_"))
        area.areas.insert(word.substr(6));
      else
        area.libraries.insert(word);
    }
    areas[name] = area;
  }
  if (areas.empty()) throw std::runtime_error(cmakeLists.string() + " has no spira_core_area() call");
  return areas;
}

std::set<std::string> readSdkAreas(const fs::path& cmakeLists)
{
  std::ifstream in(cmakeLists);
  if (!in) throw std::runtime_error("cannot read " + cmakeLists.string());
  std::set<std::string> areas;
  std::stringstream text;
  text << in.rdbuf();
  const std::string all = text.str();
  const size_t at = all.find("target_link_libraries(spira_sdk INTERFACE");
  if (at == std::string::npos)
    throw std::runtime_error(cmakeLists.string() + " has no target_link_libraries(spira_sdk INTERFACE ...)");
  std::istringstream words(all.substr(at, all.find(')', at) - at));
  for (std::string word; words >> word;)
    if (startsWith(word, "spira_") && word != "spira_sdk") areas.insert(word.substr(6));
  return areas;
}

PluginDeclaration readPluginDeclaration(const fs::path& cmakeLists)
{
  const auto [line, words] = firstCall(cmakeLists, "spira_add_plugin");
  PluginDeclaration out;
  out.line = line;
  static const std::set<std::string> keywords = {"NAME", "SOURCES", "AREAS", "LIBRARIES", "PUBLIC_HEADERS"};
  std::string keyword;
  for (const std::string& word : words) {
    if (keywords.count(word))
      keyword = word;
    else if (keyword == "AREAS")
      out.areas.insert(word);
    else if (keyword == "PUBLIC_HEADERS")
      out.publicHeaders.insert(word);
  }
  return out;
}

std::vector<Violation> checkTree(const fs::path& root)
{
  return Checker(root).run();
}

}  // namespace spira::layering
