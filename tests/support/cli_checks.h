// What every tool promises for bad input, checked the same way everywhere:
// exit code 2 and one line on stderr saying what was wrong.
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "tests/support/run_command.h"

namespace coolgas::test {

// Exit code 2 and one stderr line containing `needle`; `what` (the command's
// arguments, say) is shown if the exit code differs.
inline void expect_refused_with_one_line(const CommandResult& r, const std::string& needle,
                                         const std::string& what = "") {
  EXPECT_EQ(r.exit_code, 2) << what << "\n" << r.err;
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find(needle), std::string::npos) << r.err;
}

// As expect_refused_with_one_line, and nothing on stdout (no half table).
inline void expect_one_error_line(const CommandResult& r, const std::string& needle) {
  expect_refused_with_one_line(r, needle);
  EXPECT_TRUE(r.out.empty()) << r.out;
}

}  // namespace coolgas::test
