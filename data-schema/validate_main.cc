// coolgas-validate FILE: checks a trajectory against the coolgas H5MD profile.
// Problems go to stdout, one line each, so they can be piped and counted;
// a file that cannot be opened at all is one error line on stderr.
#include <CLI/CLI.hpp>
#include <iostream>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/tool_main.h"
#include "data-schema/validator.h"

namespace {

constexpr const char* kDescription =
    "Checks a trajectory file against the coolgas H5MD profile (data-schema/h5md-profile.md, installed as\n"
    "share/doc/coolgas/data-schema/h5md-profile.md):\n"
    "every listed group, attribute, element and dataset exists with its type and shape;\n"
    "h5md version [1, 1], author and creator; box dimension 3, boundary periodic x3, edges diag(L, L, L);\n"
    "N from /parameters/N matches the particle arrays; particle elements share F rows, observables K rows\n"
    "(each observable's rows up to the last complete dump); every series is chunked with unlimited rows;\n"
    "times never decrease; positions lie in [0, L); velocities and observables are finite;\n"
    "no two spheres overlap in any dump (aggregates by their diameters);\n"
    "/restart has F rows and the dump times; /parameters holds every documented attribute.\n"
    "F counts the complete dumps (rows of /restart/time); rows after the last of them, which a killed\n"
    "or still running writer leaves, are not checked.\n"
    "Objects the profile does not list are ignored (schema versions only add).\n"
    "Output: 'FILE: valid (...)' and exit 0, or one line 'FILE: PATH: PROBLEM' per problem on stdout\n"
    "and exit 2. A missing or non-HDF5 file: one error line on stderr, exit 2.\n"
    "SIGINT/SIGTERM/SIGHUP stop the check with one line on stderr and exit 3.";

}  // namespace

int main(int argc, char** argv) {
  return coolgas::run_tool("coolgas-validate", [&]() -> int {
    coolgas::watch_interrupts();  // reading every dump of a large file takes minutes: exit code 3
    CLI::App app(kDescription, "coolgas-validate");
    std::string file;
    app.add_option("FILE", file, "trajectory file (HDF5) to check")->required();
    if (coolgas::parse_command_line(app, argc, argv)) return 0;
    const auto report = coolgas::schema::validate(file);
    if (report.valid()) {
      std::cout << coolgas::schema::valid_line(file, report.summary, report.summary.schema_version) << "\n";
      return coolgas::kExitOk;
    }
    for (const auto& p : report.problems) std::cout << coolgas::schema::problem_line(file, p) << "\n";
    return coolgas::kExitInput;
  });
}
