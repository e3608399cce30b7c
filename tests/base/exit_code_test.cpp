#include <gtest/gtest.h>

#include <new>
#include <stdexcept>
#include <string>

#include "spira/base/error.h"
#include "spira/base/exit_code.h"
#include "spira/base/progress.h"

namespace spira {
namespace {

template <typename E>
Failure failureFrom(const E& e)
{
  return failureOf(std::make_exception_ptr(e));
}

bool saysItIsABug(const Failure& f)
{
  return f.message.find("internal error") != std::string::npos &&
         f.message.find("please report") != std::string::npos;
}

TEST(ExitCode, APartSpiraCannotPlanIsBadInputWithItsHintNotABug)
{
  const Failure f = failureFrom(AlgorithmError("the part branches at 12 mm from the base",
                                               "remesh the part more finely around the junction"));
  EXPECT_EQ(f.exitCode, kExitBadInput);
  EXPECT_EQ(f.message,
            "the part branches at 12 mm from the base (remesh the part more finely around the junction)");
  EXPECT_FALSE(saysItIsABug(f));
}

TEST(ExitCode, RunningOutOfMemoryIsForTheUserToChangeNotABug)
{
  const Failure f = failureFrom(std::bad_alloc());
  EXPECT_EQ(f.exitCode, kExitBadInput);
  EXPECT_NE(f.message.find("coarser mesh"), std::string::npos);
  EXPECT_FALSE(saysItIsABug(f));
}

TEST(ExitCode, InputAndFileErrorsAreBadInputAndInfeasiblePlansAreFour)
{
  EXPECT_EQ(failureFrom(InputError("bad mesh", "repair it")).exitCode, kExitBadInput);
  EXPECT_EQ(failureFrom(IoError("cannot read a.stl", "check the path")).exitCode, kExitBadInput);
  const Failure infeasible = failureFrom(InfeasibleError("3 unreachable points", "use --force"));
  EXPECT_EQ(infeasible.exitCode, kExitInfeasible);
  EXPECT_EQ(infeasible.message, "3 unreachable points (use --force)");
  EXPECT_EQ(failureFrom(Cancelled()).exitCode, kExitCancelled);
}

TEST(ExitCode, BrokenInvariantsAndForeignExceptionsAreBugsNeverBadInput)
{
  const Failure internal = failureFrom(InternalError("nothing to undo"));
  EXPECT_EQ(internal.exitCode, kExitInternal);
  EXPECT_TRUE(saysItIsABug(internal));
  const Failure foreign = failureFrom(std::out_of_range("vector::at"));
  EXPECT_EQ(foreign.exitCode, kExitInternal);
  EXPECT_TRUE(saysItIsABug(foreign));
  EXPECT_EQ(failureOf(std::make_exception_ptr(42)).exitCode, kExitInternal);
}

}  // namespace
}  // namespace spira
