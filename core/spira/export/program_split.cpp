#include "spira/export/program_split.h"

namespace spira {

std::vector<IndexRange> splitEvenly(size_t count, size_t maxPerPart)
{
  std::vector<IndexRange> ranges;
  if (count == 0) return ranges;
  if (maxPerPart == 0) maxPerPart = 1;
  const size_t parts = (count + maxPerPart - 1) / maxPerPart;
  const size_t base = count / parts;
  const size_t larger = count % parts;  // this many parts hold one index more
  size_t begin = 0;
  for (size_t i = 0; i < parts; ++i) {
    const size_t size = base + (i < larger ? 1 : 0);
    ranges.push_back({begin, begin + size});
    begin += size;
  }
  return ranges;
}

}  // namespace spira
