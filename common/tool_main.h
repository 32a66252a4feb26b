// The body of every coolgas main(): run the tool, turn exceptions into one
// line on stderr and the documented exit code.
#pragma once
#include <functional>
#include <string>

namespace coolgas {

// Calls body(); InputError -> "<tool>: error: <what>" and exit code 2,
// any other std::exception -> "<tool>: internal error: <what>" and exit 1.
int run_tool(const std::string& tool, const std::function<int()>& body);

}  // namespace coolgas
