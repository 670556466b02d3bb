#pragma once
// Typed errors. The command line maps InputError to exit status 2 and anything else to 1.

#include <stdexcept>
#include <string>

namespace dg {

/// Bad input from the user: unreadable or malformed file, impossible option, empty model.
/// The message names the file (when there is one) and the problem in one line.
struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A stage gave up on purpose (limit reached, cancelled); the message says which limit.
struct LimitError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace dg
