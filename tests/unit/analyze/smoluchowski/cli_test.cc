// coolgas-smoluchowski as a user runs it: table shapes, the time convention
// switch, and one clear error line with exit code 2 for bad input.
#include <gtest/gtest.h>

#include <sstream>

#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;
using test::line_count;
using test::run_command;

// common/tsv.cc takes the last comment before the first row as the column
// line, which for N(m,t) tables is the block comment "# t = ..."; drop block
// comments before reading (the row_block indices stay right).
Table parse(const std::string& text) {
  std::istringstream lines(text);
  std::string kept, line;
  while (std::getline(lines, line))
    if (line.rfind("# t = ", 0) != 0) kept += line + "\n";
  std::istringstream in(kept);
  return read_table(in, "stdout");
}

TEST(SmoluchowskiCli, BadInputGetsOneLineAndExitCodeTwo) {
  for (const char* args : {"--kernel bogus --t-end 1", "--kernel separable:1,2 --t-end 1",
                           "--kernel separable:-1,0,0 --t-end 1", "--t-end -1", "--t-end=-1", "--times 1,-2",
                           "--M 1 --t-end 1", "--method magic --t-end 1", "--convention other --t-end 1",
                           "--stepper euler --t-end 1", "--grid-ratio 1 --method geometric --t-end 1",
                           "--until-mean-mass 0.5", "", "--no-such-option"}) {
    const auto r = run_command(bin("coolgas-smoluchowski") + " " + args);
    EXPECT_EQ(r.exit_code, 2) << args;
    EXPECT_EQ(line_count(r.err), 1) << args << ": " << r.err;
    EXPECT_EQ(r.err.rfind("coolgas-smoluchowski: error: ", 0), 0u) << r.err;
  }
}

TEST(SmoluchowskiCli, SeriesStartsFromMonodisperseAndConservesMass) {
  const auto r = run_command(bin("coolgas-smoluchowski") + " --kernel constant --M 512 --t-end 10 --series");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table t = parse(r.out);
  EXPECT_EQ(t.columns, (std::vector<std::string>{"t", "M0", "M1", "M2", "M_avg", "M_max", "largest_fraction"}));
  EXPECT_EQ(t.rows.front()[0], 0);
  EXPECT_EQ(t.rows.front()[1], 1);  // c_1(0) = 1
  for (double m1 : t.column_values("M1")) EXPECT_NEAR(m1, 1, 1e-10);
  // Constant kernel: M0 = 1/(1 + t/2), exact (Leyvraz 2003, Sec. 2.1).
  EXPECT_NEAR(t.rows.back()[1], 1.0 / 6, 1e-8);
  EXPECT_EQ(t.get("convention").value().rfind("half", 0), 0u);
}

TEST(SmoluchowskiCli, PaperConventionRunsTwiceAsFast) {
  // Eq. (3) of the paper is the ½-gain equation in time t/2.
  const std::string base = bin("coolgas-smoluchowski") + " --kernel ballistic --M 1024 --method fft";
  const auto half = run_command(base + " --t-end 6");
  const auto paper = run_command(base + " --t-end 3 --convention paper");
  ASSERT_EQ(half.exit_code, 0) << half.err;
  ASSERT_EQ(paper.exit_code, 0) << paper.err;
  const Table a = parse(half.out), b = parse(paper.out);
  EXPECT_EQ(a.columns, (std::vector<std::string>{"t", "m", "dm", "N", "x", "y"}));
  ASSERT_EQ(a.rows.size(), b.rows.size());
  for (std::size_t i = 0; i < a.rows.size(); ++i) {
    EXPECT_EQ(b.rows[i][0], 3);
    EXPECT_EQ(a.rows[i][0], 6);
    EXPECT_NEAR(b.rows[i][3], a.rows[i][3], 1e-9 * a.rows[i][3]);
  }
}

TEST(SmoluchowskiCli, WarnsWithTheNeededCutoffWhenMassLeaks) {
  const auto r = run_command(bin("coolgas-smoluchowski") + " --kernel constant --M 64 --t-end 40");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("rerun with --M "), std::string::npos) << r.err;
}

TEST(SmoluchowskiCli, StopsWhenTheMeanMassIsReached) {
  const auto r = run_command(bin("coolgas-smoluchowski") + " --kernel constant --M 512 --until-mean-mass 5 --series");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const Table t = parse(r.out);
  // Constant kernel: M_avg = 1 + t/2 reaches 5 at t = 8.
  EXPECT_NEAR(t.rows.back()[0], 8, 1e-6);
  EXPECT_NEAR(t.rows.back()[4], 5, 1e-8);
}

}  // namespace
}  // namespace coolgas
