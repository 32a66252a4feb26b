// Errors shared by every coolgas program.
//
// InputError is the user's mistake (bad scene, bad option, bad file): the
// program prints its message as one line and exits with code 2. Anything else
// is a bug or an environment failure and exits with code 1, except a failed
// write (WriteError), which exits with code 5.
#pragma once
#include <stdexcept>
#include <string>

namespace coolgas {

struct InputError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Writing an output failed (disk full, quota, file-size limit, I/O error):
// the message names the file and the system's reason; exit code 5. What was
// written before the failure stays intact.
struct WriteError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// Exit codes used by every tool.
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,
  kExitInput = 2,
  kExitInterrupted = 3,
  kExitCollapse = 4,
  kExitWrite = 5,
};

}  // namespace coolgas
