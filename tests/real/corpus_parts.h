#pragma once

#include <string>
#include <vector>

namespace spira::test::real {

// What a WAAM user should get from 'spira-cli plan' on a part.
enum class Expect {
  Plans,    // exit 0, and the trajectory passes the test-side deposit check
  Refuses,  // exit 3 or 4 with an actionable hint that names the problem
  Either,   // one of the two: a hard part the product may plan or refuse, but not botch
};

// The expectation of one (part, strategy) case.
struct Expectation {
  Expect expect = Expect::Either;
  std::vector<std::string> hintWords;   // a refusal must mention one of these (none: any hint)
  std::vector<std::string> wrongWords;  // a refusal mentioning one of these misdiagnoses the part
};

// A strategy whose expectation differs from the part's (e.g. one that plans open parts only).
struct StrategyExpectation {
  std::string strategy;
  Expectation expectation;
};

// One file of tests/data/real (its origin and licence are in SOURCES.md).
struct CorpusPart {
  std::string file;
  std::string kind;
  std::string unit;         // the file's length unit, passed as --unit (mm, cm, m, in)
  double substrateZ = 0.0;  // mm: the plane the part stands on (its lowest point), --substrate-z
  Expectation expectation;
  std::vector<StrategyExpectation> byStrategy;
  std::vector<std::string> flags = {};  // more spira-cli plan flags (--level-base)
};

const std::vector<CorpusPart>& corpusParts();
const std::vector<std::string>& corpusStrategies();
const Expectation& expectationFor(const CorpusPart& part, const std::string& strategy);

// A case today's product does not meet, with the reason: the test still asserts it is sound,
// prints the reason, and fails once the product meets the expectation (so the mark is removed,
// never left stale).
struct KnownFailure {
  std::string file;
  std::string strategy;  // "*" for every strategy
  std::string reason;
};

// The mark of a (file, strategy) case, or null if it has none.
const KnownFailure* knownFailure(const std::string& file, const std::string& strategy);

}  // namespace spira::test::real
