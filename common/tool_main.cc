#include "common/tool_main.h"

#include <CLI/CLI.hpp>
#include <iostream>

#include "common/error.h"

namespace coolgas {

int run_tool(const std::string& tool, const std::function<int()>& body) {
  try {
    return body();
  } catch (const InputError& e) {
    std::cerr << tool << ": error: " << e.what() << "\n";
    return kExitInput;
  } catch (const WriteError& e) {
    std::cerr << tool << ": error: " << e.what() << "\n";
    return kExitWrite;
  } catch (const std::exception& e) {
    std::cerr << tool << ": internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}

bool parse_command_line(CLI::App& app, int argc, char** argv) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    app.exit(e);
    return true;
  } catch (const CLI::ParseError& e) {
    throw InputError(std::string(e.what()) + " (see --help)");
  }
  return false;
}

}  // namespace coolgas
