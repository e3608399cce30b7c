#pragma once

#include <stdexcept>
#include <string>

namespace spira {

// The one error root. Every message says what is wrong; `hint()` says what the user can do.
// Cancellation is not an error (see Cancelled in progress.h).
class Error : public std::runtime_error {
 public:
  Error(const std::string& what, std::string hint = {});
  const std::string& hint() const noexcept { return hint_; }
  // Message and hint on one line, as the CLI prints them.
  std::string fullMessage() const;

 private:
  std::string hint_;
};

// Input the user can fix: a bad mesh, an unsupported file, a parameter out of range, an unreachable pose.
class InputError : public Error {
 public:
  using Error::Error;
};

// Reading or writing files failed (missing, unreadable, unwritable).
class IoError : public Error {
 public:
  using Error::Error;
};

// The algorithm could not produce a result for valid input (did not converge, no solution).
class AlgorithmError : public Error {
 public:
  using Error::Error;
};

// A plan exists but violates the process window or the cell's limits.
class InfeasibleError : public Error {
 public:
  using Error::Error;
};

// A bug in Spira: an invariant broke. Users should report these.
class InternalError : public Error {
 public:
  using Error::Error;
};

}  // namespace spira
