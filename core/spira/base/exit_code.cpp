#include "spira/base/exit_code.h"

#include <new>

#include "spira/base/error.h"
#include "spira/base/progress.h"

namespace spira {

Failure failureOf(std::exception_ptr error)
{
  const auto bug = [](const std::string& what) {
    return Failure{kExitInternal, "internal error: " + what + " (please report this)"};
  };
  try {
    std::rethrow_exception(error);
  } catch (const InfeasibleError& e) {
    return {kExitInfeasible, e.fullMessage()};
  } catch (const InputError& e) {
    return {kExitBadInput, e.fullMessage()};
  } catch (const IoError& e) {
    return {kExitBadInput, e.fullMessage()};
  } catch (const AlgorithmError& e) {
    return {kExitBadInput, e.fullMessage()};
  } catch (const Error& e) {
    return bug(e.fullMessage());
  } catch (const Cancelled&) {
    return {kExitCancelled, "cancelled"};
  } catch (const std::bad_alloc&) {
    return {kExitBadInput, "out of memory (try a coarser mesh or close other programs)"};
  } catch (const std::exception& e) {
    return bug(e.what());
  } catch (...) {
    return bug("an unknown exception");
  }
}

}  // namespace spira
