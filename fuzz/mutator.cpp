#include "mutator.h"

#include <algorithm>
#include <cctype>
#include <cstring>
#include <iterator>

namespace spira::fuzz {
namespace {

// Edge values and the keywords of the formats Spira reads (STL, OBJ, PLY, JSON, URDF, CSV, the
// project header), so that mutations reach past the first syntax check.
const char* const kTokens[] = {"nan",
                               "inf",
                               "-inf",
                               "1e400",
                               "-1e400",
                               "4.9e-324",
                               "1e308",
                               "-0",
                               "0",
                               "-1",
                               "2147483648",
                               "4294967296",
                               "18446744073709551616",
                               "99999999",
                               "0x10",
                               "1.5",
                               "\n",
                               "\r\n",
                               "\t",
                               " ",
                               "\"",
                               "{",
                               "}",
                               "[",
                               "]",
                               ":",
                               ",",
                               "null",
                               "true",
                               "false",
                               "\\",
                               "/",
                               "e",
                               "#",
                               "solid a\n",
                               "facet normal 0 0 1\n",
                               "outer loop\n",
                               "vertex 0 0 0\n",
                               "endloop\n",
                               "endfacet\n",
                               "endsolid\n",
                               "ply\n",
                               "format ascii 1.0\n",
                               "format binary_little_endian 1.0\n",
                               "format binary_big_endian 1.0\n",
                               "element vertex 3\n",
                               "element face 1\n",
                               "property float x\n",
                               "property double z\n",
                               "property list uchar int vertex_indices\n",
                               "comment c\n",
                               "end_header\n",
                               "v 1 2 3\n",
                               "f 1 2 3\n",
                               "f -1 -2 -3\n",
                               "f 1/1/1 2//2 3/3\n",
                               "vn 0 0 1\n",
                               "o x\n",
                               "\\\n",
                               "<robot name=\"r\">",
                               "<link name=\"tool0\"/>",
                               "<link name=\"base_link\"/>",
                               "<joint name=\"j\" type=\"revolute\">",
                               "<parent link=\"base_link\"/>",
                               "<child link=\"tool0\"/>",
                               "<origin xyz=\"0 0 1\" rpy=\"0 0 0\"/>",
                               "<axis xyz=\"0 0 1\"/>",
                               "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>",
                               "</joint>",
                               "</robot>",
                               "\"xyz_mm\": [0, 0, 0]",
                               "\"rpy_deg\": [0, 0, 0]",
                               "\"urdf\": \"\"",
                               "\"feasible\": false",
                               "SPIRAPRJ"};

// Bytes and integers that sit on the edges of the types readers use for counts and sizes.
const uint64_t kIntegers[] = {0,
                              1,
                              2,
                              3,
                              0x7F,
                              0x80,
                              0xFF,
                              0x7FFF,
                              0xFFFF,
                              0x7FFFFFFF,
                              0x80000000,
                              0xFFFFFFFF,
                              0x7FFFFFFFFFFFFFFF,
                              0xFFFFFFFFFFFFFFFF,
                              99999999};

}  // namespace

uint64_t Mutator::next()
{
  // splitmix64: small, fast, the same everywhere.
  uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

std::string Mutator::mutate(const std::vector<std::string>& corpus)
{
  std::string s = corpus[below(corpus.size())];
  const size_t steps = 1 + below(4);
  for (size_t i = 0; i < steps; ++i) apply(s, corpus);
  if (s.size() > maxLength_) s.resize(maxLength_);
  return s;
}

void Mutator::apply(std::string& s, const std::vector<std::string>& corpus)
{
  const size_t at = below(s.size() + 1);
  switch (below(11)) {
    case 0:
      if (!s.empty()) s[at % s.size()] ^= static_cast<char>(1u << below(8));
      break;
    case 1:
      if (!s.empty()) s[at % s.size()] = static_cast<char>(next());
      break;
    case 2: {
      const size_t n = std::min(s.size() - std::min(at, s.size()), 1 + below(16));
      s.erase(at, n);
      break;
    }
    case 3: {
      std::string run(1 + below(8), '\0');
      for (char& c : run) c = static_cast<char>(next());
      s.insert(at, run);
      break;
    }
    case 4:
      if (!s.empty()) {
        const size_t from = below(s.size());
        const size_t n = std::min(s.size() - from, 1 + below(64));
        s.insert(at, s.substr(from, n));
      }
      break;
    case 5:
      s.insert(at, kTokens[below(std::size(kTokens))]);
      break;
    case 6: {
      // Replaces the number that starts at or after `at` by an edge value.
      size_t b = at;
      while (b < s.size() && !std::isdigit(static_cast<unsigned char>(s[b]))) ++b;
      size_t e = b;
      while (e < s.size() && (std::isdigit(static_cast<unsigned char>(s[e])) || s[e] == '.' || s[e] == 'e'))
        ++e;
      if (b < s.size()) s.replace(b, e - b, kTokens[below(14)]);
      break;
    }
    case 7: {
      const std::string& other = corpus[below(corpus.size())];
      s = s.substr(0, at) + other.substr(below(other.size() + 1));
      break;
    }
    case 8:
      s.resize(at);
      break;
    case 9: {
      const uint64_t v = kIntegers[below(std::size(kIntegers))];
      const size_t width = size_t{1} << below(4);
      if (s.size() >= width) {
        const size_t pos = below(s.size() - width + 1);
        std::memcpy(&s[pos], &v, width);
      }
      break;
    }
    default:
      s.insert(at, std::to_string(kIntegers[below(std::size(kIntegers))]));
      break;
  }
}

}  // namespace spira::fuzz
