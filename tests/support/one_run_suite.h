// A suite of CLI tests around one run: the scene written to a scratch
// folder and simulated once before the suite's tests, which read whole()
// and run scene() again beside it (killed, resumed, with other options).
#pragma once
#include <gtest/gtest.h>

#include <string>

#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas::test {

// Suite (the test fixture, derived from OneRunSuite<Suite>) gives
//   static constexpr const char* kFolder;  // the scratch folder's name
//   static constexpr const char* kScene;   // the scene's text
// and may give launch(args), the command line of its runs (by default a
// quiet coolgas-simulate), and after_run(), which SetUpTestSuite calls last.
template <class Suite>
class OneRunSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = scratch_dir(Suite::kFolder);
    scene_ = write_file(dir_, "scene.toml", Suite::kScene);
    const auto r = run_command(Suite::launch(scene_ + " -o " + whole()));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    Suite::after_run();
  }
  static std::string launch(const std::string& args) { return simulate(args); }
  static void after_run() {}
  static std::string whole() { return dir_ + "/whole.h5"; }
  static inline std::string dir_, scene_;
};

}  // namespace coolgas::test
