#include "spira/base/error.h"

namespace spira {

Error::Error(const std::string& what, std::string hint) : std::runtime_error(what), hint_(std::move(hint)) {}

std::string Error::fullMessage() const
{
  std::string m = what();
  if (!hint_.empty()) m += " (" + hint_ + ")";
  return m;
}

}  // namespace spira
