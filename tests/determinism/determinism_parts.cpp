#include "determinism_parts.h"

#include <cctype>
#include <filesystem>

namespace spira::test {

std::string partName(const DeterminismPart& part)
{
  std::string name = std::filesystem::path(part.file).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

void PrintTo(const DeterminismPart& part, std::ostream* out)
{
  *out << part.file;
  for (const std::string& flag : part.flags) *out << " " << flag;
  if (!part.cell.empty()) *out << " --cell " << part.cell;
  *out << " --export " << part.program;
}

}  // namespace spira::test
