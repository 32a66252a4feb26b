// Errors shared by every coolgas program.
//
// InputError is the user's mistake (bad scene, bad option, bad file): the
// program prints its message as one line and exits with code 2. Anything else
// is a bug or an environment failure (no memory, a failed write to stdout)
// and exits with code 1, except a failed write of a trajectory (WriteError),
// which exits with code 5.
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

// Longest error line a tool prints, in characters (a longer message keeps its
// beginning and end around "…").
inline constexpr std::size_t kMaxMessageChars = 200;
// Longest user-given value quoted inside a message, in characters.
inline constexpr std::size_t kMaxQuotedChars = 60;

// `text` made fit for one line of at most `max_chars` characters: control
// characters become \n, \t or \xNN; in a longer text the longest values
// (quoted texts, words such as paths) are cut around "…" first, then the text
// keeps its first two thirds and its last third (UTF-8 is never split).
std::string one_line(const std::string& text, std::size_t max_chars = kMaxMessageChars);

// A user-given value as it appears inside a message: one_line with the
// shorter limit for values.
inline std::string shown(const std::string& value) { return one_line(value, kMaxQuotedChars); }

}  // namespace coolgas
