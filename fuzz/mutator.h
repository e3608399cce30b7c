#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace spira::fuzz {

// Deterministic mutations of a corpus, for the replay driver: bit and byte changes, erased,
// repeated and inserted runs, splices of two inputs, numbers replaced by edge values (NaN,
// infinities, values beyond a double or an int, huge counts) and tokens of the formats Spira reads.
// The same seed gives the same sequence on every machine.
class Mutator {
 public:
  Mutator(uint64_t seed, size_t maxLength) : state_(seed), maxLength_(maxLength) {}
  std::string mutate(const std::vector<std::string>& corpus);

 private:
  uint64_t next();
  size_t below(size_t n) { return n == 0 ? 0 : static_cast<size_t>(next() % n); }
  void apply(std::string& s, const std::vector<std::string>& corpus);
  uint64_t state_;
  size_t maxLength_;
};

}  // namespace spira::fuzz
