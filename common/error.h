// Errors shared by every coolgas program.
//
// InputError is the user's mistake (bad scene, bad option, bad file): the
// program prints its message as one line and exits with code 2. Anything else
// is a bug or an environment failure and exits with code 1.
#pragma once
#include <stdexcept>
#include <string>

namespace coolgas {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Exit codes used by every tool.
enum ExitCode : int { kExitOk = 0, kExitFailure = 1, kExitInput = 2, kExitInterrupted = 3, kExitCollapse = 4 };

}  // namespace coolgas
