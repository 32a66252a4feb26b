// One command-line convention across the programs (README, "Analysis
// tools"): --version everywhere, usage lines with the bare program name, a
// --time that no dump has snapped with a note (or refused with
// --exact-time), no time or number that is not finite, a --series row kept
// with NaN where its fit is impossible, and old option spellings accepted
// with a note.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "common/tsv.h"
#include "common/version.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;

const char* const kPrograms[] = {"coolgas-simulate", "coolgas-validate",  "coolgas-energy",    "coolgas-fit",
                                 "coolgas-collapse", "coolgas-clusters",  "coolgas-velocity",  "coolgas-snapshot",
                                 "coolgas-shape",    "coolgas-structure", "coolgas-smoluchowski", "coolgas-fields"};

TEST(Conventions, EveryProgramPrintsItsVersionAndCommit) {
  for (const std::string program : kPrograms) {
    const auto r = run_command(bin(program) + " --version");
    EXPECT_EQ(r.exit_code, 0) << program << r.err;
    EXPECT_EQ(r.out, program + " " + program_version() + "\n");  // version.h: "0.1.0 (<commit>)"
  }
}

TEST(Conventions, UsageLinesNameTheProgramBare) {
  for (const std::string program : kPrograms) {
    const auto r = run_command(bin(program) + " --help");
    EXPECT_EQ(r.exit_code, 0) << program;
    EXPECT_NE(r.out.find("Usage: " + program + " "), std::string::npos) << r.out.substr(0, 400);
  }
}

// A mistyped option gets the closest real one, in every program (--version
// is one of each program's options, one letter away from --versoin).
TEST(Conventions, AMistypedOptionGetsADidYouMean) {
  for (const std::string program : kPrograms) {
    const auto r = run_command(bin(program) + " --versoin");
    test::expect_refused_with_one_line(r, "(did you mean '--version'?)", program);
  }
}

// A real run (N = 2000 to t = 1e4): dumps at 5 per decade, so t = 3000 and
// t = 1e6 are not dump times, t = 1000 is.
class TimeConventions : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("conventions"));
    const auto sim = run_command(test::simulate(
        "--set system.N=2000 --set system.phi=0.208 --set run.t_end=1e4 --set system.equilibrate=0 "
        "--set collision.model=inelastic --set collision.r0=0.1 --set collision.delta=1e-4 -o " + *dir +
        "/run.h5 /dev/null"));
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
  }
  static std::string run() { return *dir + "/run.h5"; }
  static inline std::string* dir = nullptr;
};

TEST_F(TimeConventions, ATimeNoDumpHasIsSnappedWithANoteOrRefused) {
  for (const std::string tool : {"coolgas-clusters", "coolgas-velocity", "coolgas-shape", "coolgas-structure"}) {
    SCOPED_TRACE(tool);
    const auto snapped = run_command(bin(tool) + " " + run() + " --series --time 3000");
    EXPECT_EQ(snapped.exit_code, 0) << snapped.err;
    EXPECT_NE(snapped.err.find("--time 3000: no dump at that time, the nearest is t = 2511.88"), std::string::npos)
        << snapped.err;
    const auto beyond = run_command(bin(tool) + " " + run() + " --series --time 1e6");
    EXPECT_NE(beyond.err.find("the nearest is t = 10000"), std::string::npos) << beyond.err;
    const auto exact = run_command(bin(tool) + " " + run() + " --series --time 1000");
    EXPECT_EQ(exact.err, "");  // a dump's own time: no note
    test::expect_one_error_line(run_command(bin(tool) + " " + run() + " --series --exact-time --time 3000"),
                                "no dump at that time");
  }
  const auto snap = run_command(bin("coolgas-snapshot") + " " + run() + " --time 3000 --exact-time -o " + *dir +
                                "/never.png");
  test::expect_one_error_line(snap, "the nearest is t = 2511.88");
}

TEST_F(TimeConventions, TimeListsAreRepeatedOrCommaSeparated) {
  const auto commas = run_command(bin("coolgas-clusters") + " " + run() + " --series --time 10,1000");
  const auto repeated = run_command(bin("coolgas-clusters") + " " + run() + " --series --time 10 --time 1000");
  EXPECT_EQ(commas.exit_code, 0) << commas.err;
  EXPECT_EQ(commas.out, repeated.out);
  std::istringstream in(commas.out);
  EXPECT_EQ(read_table(in, "stdout").column_values("t"), (std::vector<double>{10, 1000}));
}

// One convention for choosing dumps in every tool that reads chosen dumps
// (common/tool_main.h, add_dump_selection): a comma-separated list equals the
// repeated option, and --exact-time refuses a time no dump has.
TEST_F(TimeConventions, EveryToolThatReadsDumpsTakesTheSameTimeOptions) {
  const std::pair<const char*, const char*> tools[] = {{"coolgas-clusters", "--series"},
                                                       {"coolgas-velocity", "--series"},
                                                       {"coolgas-shape", ""},
                                                       {"coolgas-structure", ""},
                                                       {"coolgas-fields", ""},
                                                       {"coolgas-convert", ""},
                                                       {"coolgas-displacement", ""}};
  for (const auto& [tool, extra] : tools) {
    const std::string base = bin(tool) + " " + run() + " " + extra;
    const auto commas = run_command(base + " --time 10,1000");
    const auto repeated = run_command(base + " --time 10 --time 1000");
    EXPECT_EQ(commas.exit_code, 0) << tool << ": " << commas.err;
    EXPECT_FALSE(commas.out.empty()) << tool;
    EXPECT_EQ(commas.out, repeated.out) << tool;
    test::expect_one_error_line(run_command(base + " --exact-time --time 3000"), "no dump at that time");
  }
  // A picture shows one dump: a list is refused by name.
  test::expect_one_error_line(
      run_command(bin("coolgas-snapshot") + " " + run() + " --time 10,1000 -o " + *dir + "/two.png"),
      "give one --time");
}

// A file named by -o that exists is replaced only with --force, in every
// program that writes one (coolgas-simulate, coolgas-snapshot).
TEST_F(TimeConventions, AnExistingOutputIsReplacedOnlyWithForce) {
  const std::string png = *dir + "/exists.png";
  std::ofstream(png) << "old";
  const std::string snap = bin("coolgas-snapshot") + " " + run() + " --time 1000 -o " + png;
  test::expect_one_error_line(run_command(snap), "--force");
  EXPECT_EQ(run_command(snap + " --force").exit_code, 0);
  const std::string sim = test::simulate("--set system.N=200 --set system.phi=0.1 --set run.t_end=1 -o " + png + " /dev/null");
  test::expect_one_error_line(run_command(sim), "--force");
}

// --min-count 1e6 leaves no tail bin in any dump of 2000 particles: every
// row stays, with v_rms and kappa, beta NaN and one note per dump.
TEST_F(TimeConventions, VelocitySeriesKeepsADumpWhoseTailCannotBeFitted) {
  const auto r = run_command(bin("coolgas-velocity") + " " + run() + " --series --min-count 1e6 --time 0,1000");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(test::line_count(r.err), 2) << r.err;
  EXPECT_NE(r.err.find("beta is nan in that row"), std::string::npos) << r.err;
  int rows = 0;
  std::istringstream in(r.out);
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#' || line[0] == 't') continue;
    double t, v_rms, kappa, kappa_err;
    char beta[8] = {};
    ASSERT_EQ(std::sscanf(line.c_str(), "%lf %lf %lf %lf %7s", &t, &v_rms, &kappa, &kappa_err, beta), 5) << line;
    EXPECT_GT(v_rms, 0);
    EXPECT_STREQ(beta, "nan");
    ++rows;
  }
  EXPECT_EQ(rows, 2);
}

// The canonical pipe without a window fits the scaling window's rule
// (analyze/curves/scaling_window.h) and says so: it ends at the finite-size
// crossover 0.1 L^(5/2) = 121.6 of this box (L = 17.14).
TEST_F(TimeConventions, TheCanonicalPipeFitsTheScalingWindowWithANote) {
  const auto r = run_command(bin("coolgas-energy") + " " + run() + " | " + bin("coolgas-fit") + " --power -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("no --t-window: fitting t = "), std::string::npos) << r.err;
  std::istringstream in(r.out);
  const Table fit = read_table(in, "stdout");
  EXPECT_GT(fit.column_values("t_min")[0], 1);  // past the flat start
  EXPECT_LE(fit.column_values("t_max")[0], 0.1 * std::pow(std::cbrt(2000 * M_PI / 6 / 0.208), 2.5));
  EXPECT_GT(fit.column_values("theta")[0], 1);  // a cooling gas, not the flat start (theta near 0)
  EXPECT_LT(fit.column_values("theta")[0], 2);
}

// A time or number that is not finite is refused by every tool (exit 2, one
// line naming the option): CLI11 reads "nan" and "inf" as doubles, and a NaN
// time used to snap to the first dump with only a note.
TEST_F(TimeConventions, NonFiniteTimesAndNumbersAreRefusedWithOneLine) {
  const std::string energy = bin("coolgas-energy") + " " + run() + " | ";
  const std::string cases[][2] = {
      {bin("coolgas-velocity") + " " + run() + " --time nan", "--time nan"},
      {bin("coolgas-clusters") + " " + run() + " --time inf", "--time inf"},
      {bin("coolgas-shape") + " " + run() + " --series --time 10,-inf", "--time -inf"},
      {bin("coolgas-structure") + " " + run() + " --time NaN", "--time NaN"},
      {bin("coolgas-fields") + " " + run() + " --cell inf", "--cell inf"},
      {bin("coolgas-convert") + " " + run() + " --time inf", "--time inf"},
      {bin("coolgas-displacement") + " " + run() + " --from nan", "--from nan"},
      {bin("coolgas-snapshot") + " " + run() + " --time nan -o " + *dir + "/never.png", "--time nan"},
      {energy + bin("coolgas-fit") + " --power --window nan:1e3 -", "--t-window nan:1e3"},
      {energy + bin("coolgas-fit") + " --local-slope --smooth inf -", "--smooth inf"},
      {energy + bin("coolgas-collapse") + " --theta nan -", "--theta nan"},
      {energy + bin("coolgas-collapse") + " --z inf -", "--z inf"},
      {bin("coolgas-smoluchowski") + " --kernel constant --M 64 --grid-ratio nan --t-end 1", "--grid-ratio nan"},
      {bin("coolgas-smoluchowski") + " --kernel constant --M 64 --rtol inf --t-end 1", "--rtol inf"},
  };
  for (const auto& [command, option] : cases)
    test::expect_one_error_line(run_command(command), option + ": not a finite number");
}

TEST_F(TimeConventions, OldSpellingsStillWorkWithANote) {
  const std::string energy = bin("coolgas-energy") + " " + run() + " | ";
  const auto old_spelling = run_command(energy + bin("coolgas-fit") + " --power --window 10:1000 -");
  const auto new_spelling = run_command(energy + bin("coolgas-fit") + " --power --t-window 10:1000 -");
  EXPECT_EQ(old_spelling.exit_code, 0) << old_spelling.err;
  EXPECT_EQ(old_spelling.out, new_spelling.out);
  EXPECT_NE(old_spelling.err.find("--window is the old spelling of --t-window"), std::string::npos);
  EXPECT_EQ(new_spelling.err, "");
  const auto smol = run_command(bin("coolgas-smoluchowski") + " --kernel constant --M 64 --times 1");
  EXPECT_EQ(smol.exit_code, 0) << smol.err;
  EXPECT_NE(smol.err.find("--times is the old spelling of --time"), std::string::npos) << smol.err;
}

}  // namespace
}  // namespace coolgas
