#include "spira/export/file_set.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <set>
#include <sstream>

#include "spira/base/error.h"

namespace fs = std::filesystem;

namespace spira {

namespace {

std::string errnoText()
{
  return std::strerror(errno);
}

fs::path stagingPath(const fs::path& dir, const std::string& name)
{
  std::random_device rd;
  std::ostringstream s;
  s << "." << name << ".spira-tmp" << std::hex << rd() << rd();
  return dir / s.str();
}

// Writes `bytes` to the new file `path` and syncs it; returns the error text, empty on success.
std::string writeSynced(const fs::path& path, const std::string& bytes)
{
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) return errnoText();
  const char* p = bytes.data();
  size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;
      const std::string why = errnoText();
      ::close(fd);
      return why;
    }
    p += n;
    left -= static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0) {
    const std::string why = errnoText();
    ::close(fd);
    return why;
  }
  if (::close(fd) != 0) return errnoText();
  return {};
}

void removeQuietly(const std::vector<fs::path>& paths)
{
  std::error_code ec;
  for (const auto& p : paths) fs::remove(p, ec);
}

}  // namespace

std::vector<fs::path> writeFileSet(const fs::path& dir, const std::vector<OutputFile>& files)
{
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw IoError("cannot write into '" + dir.string() + "': it is not an existing folder",
                  "create the folder or choose another output folder");
  std::set<std::string> names;
  for (const auto& f : files)
    if (f.name.empty() || !names.insert(f.name).second)
      throw InternalError("export file set has an empty or repeated file name '" + f.name + "'");

  std::vector<fs::path> staged;
  staged.reserve(files.size());
  for (const auto& f : files) {
    const fs::path tmp = stagingPath(dir, f.name);
    const std::string why = writeSynced(tmp, f.bytes);
    if (!why.empty()) {
      staged.push_back(tmp);  // may exist half-written
      removeQuietly(staged);
      throw IoError("cannot write '" + (dir / f.name).string() + "': " + why,
                    "check that the folder is writable and the disk is not full; no file was written");
    }
    staged.push_back(tmp);
  }

  std::vector<fs::path> written;
  written.reserve(files.size());
  for (size_t i = 0; i < files.size(); ++i) {
    const fs::path target = dir / files[i].name;
    fs::rename(staged[i], target, ec);
    if (ec) {
      const std::string why = ec.message();
      removeQuietly(written);
      removeQuietly(std::vector<fs::path>(staged.begin() + static_cast<std::ptrdiff_t>(i), staged.end()));
      throw IoError("cannot replace '" + target.string() + "': " + why,
                    "check that the file is not read-only or open in another program");
    }
    written.push_back(target);
  }
  // Make the renames themselves durable.
  const int dirFd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dirFd >= 0) {
    ::fsync(dirFd);
    ::close(dirFd);
  }
  return written;
}

}  // namespace spira
