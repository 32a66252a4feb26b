// Runs a program the way a user would (through /bin/sh), for CLI tests.
#pragma once
#include <string>

namespace coolgas::test {

struct CommandResult {
  int exit_code = -1;  // exit status, or 128+signal if killed
  std::string out;     // everything written to stdout
  std::string err;     // everything written to stderr
};

// Runs `command` with /bin/sh -c, capturing stdout and stderr.
CommandResult run_command(const std::string& command);

// Absolute path of a built program, e.g. bin("coolgas-simulate").
std::string bin(const std::string& program);
// Absolute path inside the source tree, e.g. source("pipelines/demo/scene.toml").
std::string source(const std::string& relative);
// A fresh empty directory under the build tree for this test case
// (test-scratch/<name>/<Suite.Test>).
std::string scratch_dir(const std::string& name);

// The whole text of a file ("" if it cannot be read).
std::string read_text(const std::string& path);

// Number of lines in s (a final line without newline counts).
int line_count(const std::string& s);

}  // namespace coolgas::test
