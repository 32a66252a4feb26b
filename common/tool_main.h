// The body of every coolgas main(): run the tool, turn exceptions into one
// line on stderr and the documented exit code.
#pragma once
#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace coolgas {

// Calls body(); InputError -> "<tool>: error: <what>" and exit code 2,
// any other std::exception -> "<tool>: internal error: <what>" and exit 1.
int run_tool(const std::string& tool, const std::function<int()>& body);

// Parses the command line with CLI11. Returns true when --help was asked for
// (the help is printed; the tool then exits 0); a bad option or value
// becomes an InputError (one line, exit code 2).
bool parse_command_line(CLI::App& app, int argc, char** argv);

}  // namespace coolgas
