// SIGINT and SIGTERM stop the long loops of the analysis tools at once
// (common/interrupt.h): a tool looping over dumps, a collapse bootstrap, a
// Smoluchowski run and the accuracy study each end with one stderr line and
// exit code 3; a table built in memory is not written at all, and the rows a
// Smoluchowski run streamed are whole lines, without the closing '# end' line.
// Each command would run for minutes; elapsed time is only a loose bound (the
// assertion is that the tool stops, not how fast).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "tests/support/gas_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;

struct Stopped {
  int code = -1;
  double seconds = 99;  // from the signal to the exit
  std::string out, err;
};

// Runs `command` in the background, sends `signal` after one second (the
// tool is then deep in its loop) and waits for it to exit.
Stopped run_and_signal(const std::string& command, const std::string& signal, const std::string& dir) {
  const std::string out = dir + "/out.txt", err = dir + "/err.txt";
  const auto r = test::run_command(command + " > " + out + " 2> " + err + " & pid=$!; sleep 1; kill -" + signal +
                                   " $pid; t0=$(date +%s.%N); wait $pid; code=$?; "
                                   "echo \"$code $(echo \"$(date +%s.%N) - $t0\" | bc)\"");
  Stopped s;
  EXPECT_EQ(std::sscanf(r.out.c_str(), "%d %lf", &s.code, &s.seconds), 2) << r.out << r.err;
  std::ifstream o(out), e(err);
  std::stringstream so, se;
  so << o.rdbuf();
  se << e.rdbuf();
  s.out = so.str();
  s.err = se.str();
  return s;
}

void expect_stopped(const Stopped& s, const std::string& signal, const std::string& what) {
  EXPECT_EQ(s.code, 3) << what << ": " << s.err;
  EXPECT_EQ(test::line_count(s.err), 1) << what << ": " << s.err;
  EXPECT_NE(s.err.find("interrupted by SIG" + signal), std::string::npos) << what << ": " << s.err;
  EXPECT_LT(s.seconds, 5.0) << what;
}

// One dump of 10^5 particles, analysed 4000 times over (--time repeats it):
// tens of seconds to minutes of work for each tool.
TEST(InterruptCli, ToolsLoopingOverDumpsStopWithOneLineAndNoTable) {
  const std::string dir = test::scratch_dir("interrupt_dumps");
  const std::string gas = dir + "/gas.h5";
  test::write_gas_file(gas, false, false, 100000, 80);
  std::string times;
  for (int i = 0; i < 4000; ++i) times += " --time 10";
  for (const char* tool : {"coolgas-clusters", "coolgas-velocity", "coolgas-structure", "coolgas-shape"}) {
    const std::string signal = std::string(tool) == "coolgas-velocity" ? "TERM" : "INT";
    const Stopped s = run_and_signal(bin(tool) + " " + gas + times, signal, dir);
    expect_stopped(s, signal, tool);
    // Between dumps ("... of 4000 dumps") or, for coolgas-structure, inside one (its S(k) shells).
    const bool where = s.err.find("of 4000 dumps; no table written") != std::string::npos ||
                       s.err.find("within a dump (its S(k) shells); no table written") != std::string::npos;
    EXPECT_TRUE(where) << tool << ": " << s.err;
    EXPECT_TRUE(s.out.empty()) << tool;
  }
}

// E(t) tables of L = 16 and 32 following Eq. (2) of the paper with theta =
// 1.2, z = 2.5 (as in energy_fit_collapse_cli_test.cc); 10^5 bootstrap
// replicas take minutes.
TEST(InterruptCli, ACollapseBootstrapStopsWithOneLineAndNoTable) {
  const std::string dir = test::scratch_dir("interrupt_collapse");
  std::string tables;
  for (double L : {16.0, 32.0}) {
    const std::string path = dir + "/E" + std::to_string(int(L)) + ".tsv";
    std::ofstream f(path);
    f << "# L: " << L << "\n# t\tE\tE_err\n";
    for (int k = 0; k <= 100; ++k) {
      const double t = std::pow(10.0, k / 20.0), x = t / std::pow(L, 2.5);
      const double E = std::pow(L, -3.0) * std::pow(x, -1.2) * std::pow(1 + x, -0.63);
      f << t << "\t" << E << "\t" << 0.01 * E << "\n";
    }
    tables += " " + path;
  }
  const Stopped s = run_and_signal(bin("coolgas-collapse") + " --optimize --t-window 1: --bootstrap 100000" + tables, "INT", dir);
  expect_stopped(s, "INT", "collapse");
  EXPECT_NE(s.err.find("; no table written"), std::string::npos) << s.err;
  EXPECT_TRUE(s.out.empty());
}

// Every line written is whole and a table row or comment; no '# end' line.
void expect_whole_rows(const std::string& out) {
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(out.find("# end"), std::string::npos);
}

// The direct method at M = 8192 runs for minutes to t = 1e5.
TEST(InterruptCli, ASmoluchowskiRunStopsBetweenTwoStepsWithWholeRows) {
  const std::string dir = test::scratch_dir("interrupt_smoluchowski");
  for (const char* signal : {"INT", "TERM"}) {
    const Stopped s = run_and_signal(
        bin("coolgas-smoluchowski") + " --kernel constant --method direct --M 8192 --t-end 1e5 --series", signal, dir);
    expect_stopped(s, signal, "smoluchowski");
    EXPECT_NE(s.err.find("the rows written so far are complete"), std::string::npos) << s.err;
    expect_whole_rows(s.out);
  }
}

TEST(InterruptCli, TheAccuracyStudyStops) {
  const std::string dir = test::scratch_dir("interrupt_accuracy");
  const Stopped s = run_and_signal(bin("coolgas-smoluchowski") + " --accuracy-study", "INT", dir);
  expect_stopped(s, "INT", "accuracy study");
}

}  // namespace
}  // namespace coolgas
