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
  } catch (const std::exception& e) {
    std::cerr << tool << ": internal error: " << e.what() << "\n";
    return kExitFailure;
  }
}

}  // namespace coolgas
