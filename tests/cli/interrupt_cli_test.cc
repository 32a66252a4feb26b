// SIGINT, SIGTERM and SIGHUP stop the long loops of the analysis tools at
// once (common/interrupt.h): a tool looping over dumps, a collapse
// bootstrap, a Smoluchowski run, the accuracy study, a table being fitted,
// runs being averaged, frames being converted, a file being validated or
// drawn each end with one stderr line and exit code 3; a table built in
// memory is not written at all, and the rows or frames a tool streamed are
// whole. Each command would run for minutes. The signal comes at a named
// point, not after a delay (common/fault_point.h, `interrupt-check`): the
// tool raises it at its K-th look at the flag, or waits there until a
// signal from outside comes, so every machine stops it at the same look.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>

#include "tests/support/fault_points.h"
#include "tests/support/gas_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;

struct Stopped {
  int code = -1;
  std::string out, err;
};

// Runs `command` with the fault `interrupt-check:LOOK:SIGNAL`: the signal
// comes at the tool's LOOK-th look at the flag.
Stopped run_and_signal(const std::string& command, int look, const std::string& signal, const std::string& dir) {
  const std::string out = dir + "/out.txt", err = dir + "/err.txt";
  const auto r = test::run_command(test::fault("interrupt-check:" + std::to_string(look) + ":" + signal) + command +
                                   " > " + out + " 2> " + err);
  return {r.exit_code, test::read_text(out), test::read_text(err)};
}

void expect_stopped(const Stopped& s, const std::string& signal, const std::string& what) {
  EXPECT_EQ(s.code, 3) << what << ": " << s.err;
  EXPECT_EQ(test::line_count(s.err), 1) << what << ": " << s.err;
  EXPECT_NE(s.err.find("interrupted by SIG" + signal), std::string::npos) << what << ": " << s.err;
}

// One dump of 10^5 particles, analysed 4000 times over (--time repeats it):
// tens of seconds to minutes of work for each tool.
TEST(InterruptCli, ToolsLoopingOverDumpsStopWithOneLineAndNoTable) {
  const std::string dir = test::scratch_dir("interrupt_dumps");
  const std::string gas = dir + "/gas.h5";
  test::write_gas_file(gas, false, false, 100000, 80);
  std::string times;
  for (int i = 0; i < 4000; ++i) times += " --time 10";
  for (const char* tool :
       {"coolgas-clusters", "coolgas-velocity", "coolgas-structure", "coolgas-shape", "coolgas-displacement"}) {
    const std::string signal = std::string(tool) == "coolgas-velocity" ? "TERM" : "INT";
    const Stopped s = run_and_signal(bin(tool) + " " + gas + times, 3, signal, dir);
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
  // The 2000th look: inside the replicas (the first search takes fewer),
  // where a signal within a replica's own search stops the loop too.
  const Stopped s =
      run_and_signal(bin("coolgas-collapse") + " --optimize --t-window 1: --bootstrap 100000" + tables, 2000, "INT", dir);
  expect_stopped(s, "INT", "collapse");
  EXPECT_NE(s.err.find(" of 100000 bootstrap replicas; no table written"), std::string::npos) << s.err;
  EXPECT_TRUE(s.out.empty());
}

// Every line written is whole and a table row or comment; no '# end' line.
void expect_whole_rows(const std::string& out) {
  ASSERT_FALSE(out.empty());
  EXPECT_EQ(out.back(), '\n');
  EXPECT_EQ(out.find("# end"), std::string::npos);
}

// The direct method at M = 8192 runs for minutes to t = 1e5; the 1000th
// look is a few steps in, some rows streamed.
TEST(InterruptCli, ASmoluchowskiRunStopsBetweenTwoStepsWithWholeRows) {
  const std::string dir = test::scratch_dir("interrupt_smoluchowski");
  for (const char* signal : {"INT", "TERM"}) {
    const Stopped s = run_and_signal(
        bin("coolgas-smoluchowski") + " --kernel constant --method direct --M 8192 --t-end 1e5 --series", 1000, signal,
        dir);
    expect_stopped(s, signal, "smoluchowski");
    EXPECT_NE(s.err.find("the rows written so far are complete"), std::string::npos) << s.err;
    expect_whole_rows(s.out);
  }
}

TEST(InterruptCli, TheAccuracyStudyStops) {
  const std::string dir = test::scratch_dir("interrupt_accuracy");
  const Stopped s = run_and_signal(bin("coolgas-smoluchowski") + " --accuracy-study", 1000, "INT", dir);
  expect_stopped(s, "INT", "accuracy study");
}

// A signal from another process, while the tool waits at its third look
// (the fault's WAIT): the same stop, "after 2 of 4000 dumps".
TEST(InterruptCli, ASignalFromOutsideStopsTheLoopAtItsNextLook) {
  const std::string dir = test::scratch_dir("interrupt_outside");
  const std::string gas = dir + "/gas.h5", ready = dir + "/ready", err = dir + "/err.txt";
  test::write_gas_file(gas);
  std::string times;
  for (int i = 0; i < 4000; ++i) times += " --time 10";
  const auto r = test::run_command(test::when_ready(test::waiting_at("interrupt-check:3", ready) +
                                                        bin("coolgas-clusters") + " " + gas + times + " 2> " + err,
                                                    ready, "kill -HUP $pid"));
  EXPECT_EQ(r.exit_code, 3) << r.err;
  // The hold says where it is (common/fault_point.h), then the signal's one line.
  EXPECT_EQ(test::read_text(err),
            "coolgas: fault: holding at COOLGAS_FAULT = 'interrupt-check:3:WAIT' until SIGINT, SIGTERM, SIGHUP or "
            "SIGCONT\ncoolgas-clusters: interrupted by SIGHUP after 2 of 4000 dumps; no table written\n");
  EXPECT_TRUE(r.out.empty());
}

// A short run's file (32 dumps), and a 1D run's (42 dumps), for the tools below.
class InterruptTools : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("interrupt_tools"));
    const std::string gas = "[system]\nN = 2000\nphi = 0.1\nseed = 3\n[collision]\nmodel = \"inelastic\"\nr0 = 0.5\n"
                            "delta = 1e-4\n[run]\nt_end = 10\n[output]\ndumps_per_decade = 10\n";
    const std::string rods = "[system]\ndimension = 1\nN = 2000\nphi = 0.3\nseed = 4\n[collision]\nmodel = "
                             "\"inelastic\"\nr0 = 0.5\ndelta = 1e-3\n[run]\nt_end = 100\n[output]\ndumps_per_decade = 10\n";
    for (const auto& [name, scene] : {std::pair{"gas", gas}, std::pair{"rods", rods}}) {
      const std::string path = *dir_ + "/" + name;
      std::ofstream(path + ".toml") << scene;
      const auto r = test::run_command(bin("coolgas-simulate") + " -q " + path + ".toml -o " + path + ".h5");
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string gas() { return *dir_ + "/gas.h5"; }
  static std::string rods() { return *dir_ + "/rods.h5"; }
  static std::string* dir_;
};
std::string* InterruptTools::dir_ = nullptr;

// Hundreds of seeds' files are minutes of reading: stopped between two.
TEST_F(InterruptTools, EnergyStopsBetweenRuns) {
  const Stopped s = run_and_signal(bin("coolgas-energy") + " " + gas() + " " + gas() + " " + gas(), 2, "TERM", *dir_);
  expect_stopped(s, "TERM", "energy");
  EXPECT_NE(s.err.find("after 1 of 3 runs; no table written"), std::string::npos) << s.err;
  EXPECT_TRUE(s.out.empty());
}

// A local slope over millions of rows, a Haff fit's iterations: stopped at the first look.
TEST_F(InterruptTools, FitStopsInALocalSlopeAndAHaffFit) {
  const std::string table = *dir_ + "/haff.tsv";
  {
    std::ofstream f(table);
    f << "t\tE\n";
    for (int k = 0; k <= 200; ++k) f << std::pow(10.0, k / 50.0) << "\t" << 1 / std::pow(1 + std::pow(10.0, k / 50.0) / 5, 2) << "\n";
  }
  for (const auto& [mode, where] : {std::pair{"--local-slope", "during the local slope; no table written"},
                                    std::pair{"--haff", "during the Haff fit; no table written"}}) {
    const Stopped s = run_and_signal(bin("coolgas-fit") + " " + mode + " " + table, 1, "INT", *dir_);
    expect_stopped(s, "INT", mode);
    EXPECT_NE(s.err.find(where), std::string::npos) << s.err;
    EXPECT_TRUE(s.out.empty()) << mode;
  }
}

// Frames stream out whole: stopped at the third look, exactly two frames
// (a count line, a comment line, 2000 particle lines each).
TEST_F(InterruptTools, ConvertStopsBetweenFramesWithWholeFrames) {
  const Stopped s = run_and_signal(bin("coolgas-convert") + " " + gas(), 3, "INT", *dir_);
  expect_stopped(s, "INT", "convert");
  EXPECT_NE(s.err.find("after 2 of 32 dumps; the frames written so far are whole"), std::string::npos) << s.err;
  EXPECT_EQ(test::line_count(s.out), 2 * 2002);
  EXPECT_EQ(s.out.back(), '\n');
}

// A 1D file's space-time picture reads every dump, then gnuplot draws it:
// stopped in either, no picture and no table, the temporary folder gone.
TEST_F(InterruptTools, SnapshotStopsBetweenDumpsAndAfterGnuplot) {
  const std::string tmp = test::scratch_dir("interrupt_snapshot_tmp"), png = *dir_ + "/rods.png";
  const std::string snapshot = "TMPDIR=" + tmp + " " + bin("coolgas-snapshot") + " " + rods() + " --time 100 -o " + png;
  const Stopped between = run_and_signal(snapshot, 3, "TERM", *dir_);
  expect_stopped(between, "TERM", "snapshot, reading dumps");
  EXPECT_NE(between.err.find("after 2 of 42 dumps; no picture or table written"), std::string::npos) << between.err;
  // The look after the 42 dumps' is the one after gnuplot.
  const Stopped after = run_and_signal(snapshot, 43, "INT", *dir_);
  expect_stopped(after, "INT", "snapshot, drawing");
  EXPECT_NE(after.err.find("while gnuplot drew the picture; no picture or table written"), std::string::npos)
      << after.err;
  for (const Stopped& s : {between, after}) EXPECT_TRUE(s.out.empty());
  EXPECT_FALSE(std::filesystem::exists(png));
  EXPECT_TRUE(std::filesystem::is_empty(tmp));
}

// Checking every dump of a large file takes minutes, in coolgas-validate and
// before a --resume: stopped at the first block read, the file unchanged,
// and a later --resume goes on.
TEST_F(InterruptTools, ValidateAndTheCheckBeforeAResumeStop) {
  const Stopped v = run_and_signal(bin("coolgas-validate") + " " + gas(), 1, "INT", *dir_);
  expect_stopped(v, "INT", "validate");
  EXPECT_NE(v.err.find("while checking the file; it is unchanged"), std::string::npos) << v.err;
  EXPECT_TRUE(v.out.empty());
  const std::string run = *dir_ + "/resumed.h5";
  std::filesystem::copy_file(gas(), run, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(gas() + ".checkpoint", run + ".checkpoint", std::filesystem::copy_options::overwrite_existing);
  const std::string before = test::read_text(run);
  const std::string resume = bin("coolgas-simulate") + " -q --resume " + run + " --set run.t_end=20";
  const Stopped r = run_and_signal(resume, 1, "TERM", *dir_);
  expect_stopped(r, "TERM", "resume");
  EXPECT_NE(r.err.find("coolgas-simulate: interrupted by SIGTERM while checking the file; it is unchanged"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(test::read_text(run) == before) << "the stopped resume changed the file";
  const auto again = test::run_command(resume);
  EXPECT_EQ(again.exit_code, 0) << again.err;
}

}  // namespace
}  // namespace coolgas
