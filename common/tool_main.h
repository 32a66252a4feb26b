// The body of every coolgas main(): run the tool, turn exceptions into one
// line on stderr and the documented exit code, and make sure the table on
// stdout was really written.
#pragma once
#include <functional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}

namespace coolgas {

// Calls body() and returns its exit code. Around it:
// - stdout (std::cout) is written through a buffer that remembers the first
//   failed write; at the end it is flushed and closed, and a failure (disk
//   full, `> /dev/full`, a closed stdout) becomes "<tool>: error: cannot
//   write stdout: <cause>" and exit code 1, as coreutils do;
// - a closed pipe (`| head`) ends the tool quietly through SIGPIPE, whose
//   default action is restored even if the parent ignored it;
// - SIGXFSZ is ignored, so a file-size limit (`ulimit -f`) makes the write
//   fail with EFBIG (reported) instead of killing the process;
// - InputError -> "<tool>: error: <what>" and exit code 2; Interrupted
//   (common/interrupt.h: SIGINT/SIGTERM in a tool that watches for them) ->
//   "<tool>: interrupted by SIGINT <where>" and exit code 3; std::bad_alloc ->
//   "out of memory" and exit 1, any other std::exception -> "<tool>:
//   internal error: <what>" and exit 1; every message is one line of at most
//   kMaxMessageChars characters (common/error.h);
// - a test's fault (COOLGAS_FAULT, common/fault_point.h) is armed first.
int run_tool(const std::string& tool, const std::function<int()>& body);

// Parses the command line with CLI11. Returns true when --help or --version
// was asked for (printed; the tool then exits 0); a bad option or value
// becomes an InputError (one line, exit code 2). Every tool gets --version
// ("<tool> <version> (<commit>)"), and its usage line names the tool bare.
bool parse_command_line(CLI::App& app, int argc, char** argv);

// The one convention of every tool that reads chosen dumps: `--time T`
// (repeatable, or a comma-separated list; [1/omega0]) picks the dump
// nearest each time, snapped with a note on stderr, and `--exact-time`
// refuses a time no dump has instead. `what` begins --time's help ("analyse
// only the dump nearest this time"). Returns the --time option.
CLI::Option* add_dump_selection(CLI::App& app, std::vector<double>& times, bool& exact_time, const std::string& what);

// An old option spelling that still works for one version: if argv uses
// `old_name` (the option must accept both names), a note on stderr at the
// end of a successful run says to use `new_name`. Call after parse_command_line.
void note_old_spelling(int argc, char** argv, const std::string& old_name, const std::string& new_name);

// "<tool>: note: <text>" on stderr: something the user should know that is
// not an error (a time snapped to a dump, a fit left out).
void note(const std::string& text);

}  // namespace coolgas
