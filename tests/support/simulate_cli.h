// Helpers for the tests that drive coolgas-simulate as a user would.
#pragma once
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"

namespace coolgas::test {

// Writes `text` to dir/name and returns the path.
inline std::string write_file(const std::string& dir, const std::string& name, const std::string& text) {
  std::string path = dir + "/" + name;
  std::ofstream(path) << text;
  return path;
}

// A cooling, clustering gas; under a second of dynamics on one core (the
// resume tests stop and resume it; with --set system.dimension=2, as disks).
inline constexpr const char* kCoolingGasScene = R"([system]
N = 8000
phi = 0.2
seed = 3
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.5
delta = 1e-3
[run]
t_end = 2000
[output]
dumps_per_decade = 10
)";

// x with 17 significant digits, which read back to the same double (for --set values).
inline std::string format_exact(double x) {
  std::ostringstream s;
  s.precision(17);
  s << x;
  return s.str();
}

// The command line of a quiet coolgas-simulate run with these arguments.
inline std::string simulate(const std::string& args) { return bin("coolgas-simulate") + " -q " + args; }

// Expects coolgas-simulate to refuse `args`: exit code 2, one stderr line
// containing `needle`, and neither `out` nor its partial file left behind.
inline void expect_simulate_refused(const std::string& args, const std::string& needle, const std::string& out) {
  expect_refused_with_one_line(run_command(simulate(args)), needle, args);
  EXPECT_FALSE(std::filesystem::exists(out)) << args;
  EXPECT_FALSE(std::filesystem::exists(out + ".partial")) << args;
}

}  // namespace coolgas::test
