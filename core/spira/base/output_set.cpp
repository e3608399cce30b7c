#include "spira/base/output_set.h"

#include <fcntl.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <set>
#include <sstream>

#include <nlohmann/json.hpp>

#include "spira/base/atomic_file.h"
#include "spira/base/error.h"

namespace fs = std::filesystem;

namespace spira {
namespace {

struct Entry {
  std::string name;
  std::uintmax_t size = 0;
  std::string sum;
  std::string program;  // the program a program file belongs to (programName)
};

struct Manifest {
  bool complete = true;
  std::vector<Entry> plan, program;
};

std::string checksum(const std::string& bytes)
{
  std::uint64_t h = 1469598103934665603ull;  // FNV-1a, 64 bits
  for (const unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  std::ostringstream s;
  s << std::hex << h;
  return s.str();
}

std::vector<Entry> entriesOf(const nlohmann::json& list)
{
  std::vector<Entry> out;
  if (!list.is_array()) return out;
  for (const auto& e : list) {
    if (!e.is_object() || !e.contains("name") || !e["name"].is_string()) continue;
    Entry entry;
    entry.name = e["name"].get<std::string>();
    if (e.contains("size") && e["size"].is_number_unsigned()) entry.size = e["size"].get<std::uintmax_t>();
    if (e.contains("fnv1a64") && e["fnv1a64"].is_string()) entry.sum = e["fnv1a64"].get<std::string>();
    if (e.contains("program") && e["program"].is_string()) entry.program = e["program"].get<std::string>();
    // A name that leaves the folder is not one Spira wrote.
    if (entry.name.empty() || entry.name.find('/') != std::string::npos || entry.name == "." ||
        entry.name == "..")
      continue;
    out.push_back(entry);
  }
  return out;
}

// The manifest of `dir`; none (empty lists) when it is missing or unreadable.
Manifest readManifest(const fs::path& dir, bool* present = nullptr)
{
  Manifest m;
  std::error_code ec;
  const fs::path file = dir / kOutputManifest;
  if (present) *present = fs::is_regular_file(file, ec);
  if (!fs::is_regular_file(file, ec)) return m;
  const nlohmann::json j = nlohmann::json::parse(readFile(file), nullptr, false);
  if (!j.is_object()) {
    m.complete = false;
    return m;
  }
  m.complete = j.contains("complete") && j["complete"].is_boolean() && j["complete"].get<bool>();
  if (j.contains("plan")) m.plan = entriesOf(j["plan"]);
  if (j.contains("program")) m.program = entriesOf(j["program"]);
  return m;
}

std::string manifestText(const Manifest& m)
{
  auto list = [](const std::vector<Entry>& entries) {
    nlohmann::json a = nlohmann::json::array();
    for (const Entry& e : entries) {
      nlohmann::json o{{"name", e.name}, {"size", e.size}, {"fnv1a64", e.sum}};
      if (!e.program.empty()) o["program"] = e.program;
      a.push_back(o);
    }
    return a;
  };
  return nlohmann::json{{"complete", m.complete}, {"plan", list(m.plan)}, {"program", list(m.program)}}.dump(
             1) +
         "\n";
}

void syncDirectory(const fs::path& dir)
{
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

// Hidden siblings of `dir` left by a run that was killed: `.<name>.spira-stage-*` (a set being
// staged) and `.<name>.spira-old-*` (the previous content, swapped out).
std::string stagePrefix(const fs::path& dir)
{
  return "." + dir.filename().string() + ".spira-stage-";
}
std::string oldPrefix(const fs::path& dir)
{
  return "." + dir.filename().string() + ".spira-old-";
}

void removeLeftovers(const fs::path& dir)
{
  std::error_code ec;
  const std::string stage = stagePrefix(dir), old = oldPrefix(dir);
  std::vector<fs::path> gone;
  for (const auto& e : fs::directory_iterator(dir.parent_path(), ec)) {
    const std::string n = e.path().filename().string();
    if (n.rfind(stage, 0) == 0 || n.rfind(old, 0) == 0) gone.push_back(e.path());
  }
  for (const auto& p : gone) fs::remove_all(p, ec);
}

// Whether `dir` can be swapped as a whole: not the working directory or one of its parents, not a
// mount point, and holding nothing but files (sub-folders are not carried into the new set).
bool swappable(const fs::path& dir)
{
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  if (!ec) {
    const auto rel = cwd.lexically_relative(dir);
    if (!rel.empty() && *rel.begin() != "..") return false;
  }
  struct stat self {
  }, parent{};
  if (::stat(dir.c_str(), &self) != 0 || ::stat(dir.parent_path().c_str(), &parent) != 0) return false;
  if (self.st_dev != parent.st_dev) return false;
  for (const auto& e : fs::directory_iterator(dir, ec))
    if (e.is_directory(ec)) return false;
  return !ec;
}

[[noreturn]] void failWriting(const fs::path& target, const std::string& why)
{
  throw IoError("cannot write '" + target.string() + "': " + why,
                "check that the folder is writable and the disk is not full; the folder was left as it was");
}

std::string programName(const std::vector<OutputFile>& files)
{
  return files.empty() ? std::string() : fs::path(files.front().name).stem().string();
}

std::vector<Entry> entriesFor(const std::vector<OutputFile>& files, const std::string& program)
{
  std::vector<Entry> out;
  for (const OutputFile& f : files) out.push_back({f.name, f.bytes.size(), checksum(f.bytes), program});
  return out;
}

// The thermal files are listed with the programs, under a name no program file can have: like a
// program they belong to the plan beside them.
constexpr const char* kThermalSet = "/thermal";
constexpr const char* kScanSet = "/scan";

// What a new set writes: its kind, its file names and, for a program, the program's name.
struct NewSet {
  NewSet(OutputKind k, const std::vector<OutputFile>& files)
      : kind(k),
        program(k == OutputKind::Program   ? programName(files)
                : k == OutputKind::Thermal ? kThermalSet
                : k == OutputKind::Scan    ? kScanSet
                                           : std::string())
  {
    for (const OutputFile& f : files) names.insert(f.name);
  }

  // Whether an old entry stays in the folder beside the new set: a plan replaces the previous
  // plan and every program (made from that plan); a program replaces the previous files of the
  // same program and keeps the plan and other programs; nothing keeps a name the new set writes.
  bool keeps(const Entry& e, bool isProgram) const
  {
    if (names.count(e.name) || kind == OutputKind::Plan) return false;
    return !isProgram || e.program != program;
  }

  OutputKind kind;
  std::string program;
  std::set<std::string> names;
};

// Names the new set drops from the folder.
std::set<std::string> dropped(const Manifest& old, const NewSet& next)
{
  std::set<std::string> names = next.names;
  names.insert(kOutputManifest);
  for (const Entry& e : old.plan)
    if (!next.keeps(e, false)) names.insert(e.name);
  for (const Entry& e : old.program)
    if (!next.keeps(e, true)) names.insert(e.name);
  return names;
}

Manifest nextManifest(const Manifest& old, const NewSet& next, const std::vector<OutputFile>& files)
{
  Manifest m;
  for (const Entry& e : old.plan)
    if (next.keeps(e, false)) m.plan.push_back(e);
  for (const Entry& e : old.program)
    if (next.keeps(e, true)) m.program.push_back(e);
  std::vector<Entry>& into = next.kind == OutputKind::Plan ? m.plan : m.program;
  const std::vector<Entry> added = entriesFor(files, next.program);
  for (size_t i = 0; i < files.size(); ++i) {
    if (next.kind == OutputKind::Plan && files[i].thermal) {
      m.program.push_back(added[i]);
      m.program.back().program = kThermalSet;
    } else {
      into.push_back(added[i]);
    }
  }
  return m;
}

std::vector<fs::path> swapIn(const fs::path& dir, const Manifest& old, OutputKind kind,
                             const std::vector<OutputFile>& files)
{
  const fs::path stage = dir.parent_path() / (stagePrefix(dir) + randomSuffix());
  std::error_code ec;
  if (!fs::create_directory(stage, ec)) failWriting(stage, ec.message());
  try {
    fs::permissions(stage, fs::status(dir).permissions(), ec);
    for (const OutputFile& f : files)
      if (const std::string why = writeSynced(stage / f.name, f.bytes); !why.empty())
        failWriting(dir / f.name, why);
    const std::set<std::string> drop = dropped(old, NewSet(kind, files));
    for (const auto& e : fs::directory_iterator(dir)) {
      const std::string n = e.path().filename().string();
      if (drop.count(n) || n.rfind(".spira-tmp-", 0) == 0) continue;
      fs::create_hard_link(e.path(), stage / n, ec);
      if (ec) fs::copy(e.path(), stage / n, fs::copy_options::copy_symlinks, ec);
      if (ec) failWriting(dir / n, "cannot keep it in the new set: " + ec.message());
    }
    if (const std::string why =
            writeSynced(stage / kOutputManifest, manifestText(nextManifest(old, NewSet(kind, files), files)));
        !why.empty())
      failWriting(dir / kOutputManifest, why);
    syncDirectory(stage);
    if (::renameat2(AT_FDCWD, stage.c_str(), AT_FDCWD, dir.c_str(), RENAME_EXCHANGE) != 0) {
      if (errno != EINVAL && errno != ENOSYS && errno != ENOTSUP) failWriting(dir, errnoText());
      const fs::path aside = dir.parent_path() / (oldPrefix(dir) + randomSuffix());
      if (::rename(dir.c_str(), aside.c_str()) != 0) failWriting(dir, errnoText());
      if (::rename(stage.c_str(), dir.c_str()) != 0) {
        const std::string why = errnoText();
        ::rename(aside.c_str(), dir.c_str());
        failWriting(dir, why);
      }
      fs::remove_all(aside, ec);
    }
  } catch (...) {
    fs::remove_all(stage, ec);
    throw;
  }
  fs::remove_all(stage, ec);  // the previous content, swapped out
  syncDirectory(dir.parent_path());
  std::vector<fs::path> written;
  for (const OutputFile& f : files) written.push_back(dir / f.name);
  return written;
}

std::vector<fs::path> renameIn(const fs::path& dir, const Manifest& old, OutputKind kind,
                               const std::vector<OutputFile>& files)
{
  std::error_code ec;
  for (const OutputFile& f : files)
    if (fs::is_directory(dir / f.name, ec))
      throw IoError("cannot write '" + (dir / f.name).string() + "': a folder of that name is in the way",
                    "move or rename that folder; the output folder was left as it was");
  std::vector<fs::path> staged;
  auto cleanUp = [&] {
    for (const auto& p : staged) fs::remove(p, ec);
  };
  for (const OutputFile& f : files) {
    staged.push_back(dir / (".spira-tmp-" + randomSuffix() + "-" + f.name));
    if (const std::string why = writeSynced(staged.back(), f.bytes); !why.empty()) {
      cleanUp();
      failWriting(dir / f.name, why);
    }
  }
  // From here until the manifest is rewritten the folder holds a mix, which readers refuse.
  Manifest flux = old;
  flux.complete = false;
  if (const std::string why = writeSynced(dir / kOutputManifest, manifestText(flux)); !why.empty()) {
    cleanUp();
    failWriting(dir / kOutputManifest, why);
  }
  for (const std::string& n : dropped(old, NewSet(kind, files)))
    if (n != kOutputManifest) fs::remove(dir / n, ec);
  std::vector<fs::path> written;
  for (size_t i = 0; i < files.size(); ++i) {
    const fs::path target = dir / files[i].name;
    if (::rename(staged[i].c_str(), target.c_str()) != 0) failWriting(target, errnoText());
    written.push_back(target);
  }
  if (const std::string why =
          writeSynced(dir / kOutputManifest, manifestText(nextManifest(old, NewSet(kind, files), files)));
      !why.empty())
    failWriting(dir / kOutputManifest, why);
  syncDirectory(dir);
  return written;
}

}  // namespace

std::vector<fs::path> replaceOutputSet(const fs::path& folder, OutputKind kind,
                                       const std::vector<OutputFile>& files)
{
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw IoError("cannot write into '" + folder.string() + "': it is not an existing folder",
                  "create the folder or choose another output folder");
  std::set<std::string> names;
  for (const auto& f : files)
    if (f.name.empty() || f.name.find('/') != std::string::npos || f.name == kOutputManifest ||
        !names.insert(f.name).second)
      throw InternalError("output set has an empty, repeated or reserved file name '" + f.name + "'");
  const fs::path dir = fs::canonical(folder, ec);
  if (ec)
    throw IoError("cannot write into '" + folder.string() + "': " + ec.message(),
                  "choose another output folder");
  removeLeftovers(dir);
  const Manifest old = readManifest(dir);
  return swappable(dir) ? swapIn(dir, old, kind, files) : renameIn(dir, old, kind, files);
}

void verifyOutputSet(const fs::path& dir)
{
  bool present = false;
  const Manifest m = readManifest(dir, &present);
  if (!present) return;
  const std::string again = "plan it again (spira-cli plan, or Plan in Spira) to write a whole set";
  if (!m.complete)
    throw InputError("the folder '" + dir.string() +
                         "' holds an incomplete set of files: a plan or export "
                         "was interrupted while writing it",
                     again);
  for (const auto* list : {&m.plan, &m.program})
    for (const Entry& e : *list) {
      const fs::path file = dir / e.name;
      std::error_code ec;
      if (!fs::is_regular_file(file, ec))
        throw InputError("'" + file.string() + "' is missing from the set of files its folder lists", again);
      if (fs::file_size(file, ec) != e.size || checksum(readFile(file)) != e.sum)
        throw InputError(
            "'" + file.string() +
                "' is not the file written with the rest of its folder (changed by hand, or left "
                "by an interrupted run)",
            again);
    }
}

}  // namespace spira
