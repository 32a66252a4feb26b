// Every command of README.md and pipelines/README.md runs and exits 0
// (tests/cli/readme_commands.py says how they are found, which small inputs
// stand in for the documented files, and which are skipped and why).
#include <gtest/gtest.h>

#include "tests/support/run_command.h"

namespace coolgas {
namespace {

TEST(ReadmeCommands, EveryDocumentedCommandRuns) {
  const std::string dir = test::scratch_dir("readme_commands");
  const auto r = test::run_command("/usr/bin/python3 " + test::source("tests/cli/readme_commands.py") + " " +
                                   test::source("") + " " + test::bin("") + " " + dir);
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace coolgas
