// Every reader a user reaches for gets the names and every row of a real
// tool's table (data-schema/tsv-tables.md, format 2): pandas
// read_csv(sep='\t', comment='#'), numpy genfromtxt(names=True) and
// loadtxt(skiprows=1), gnuplot by column name and by number.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;

class TableReaders : public ::testing::Test {
 protected:
  // One small real run (N = 500, to t = 100) and three tables of it: a plain
  // series, a table of blocks (one per dump) and a one-row fit.
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("table_readers"));
    const std::string run = *dir + "/run.h5";
    const auto sim = run_command(test::simulate("--set system.N=500 --set system.phi=0.2 --set run.t_end=100 "
                                                "--set system.equilibrate=0 --set collision.model=inelastic --set collision.r0=0.1 "
                                                "--set collision.delta=1e-4 -o " + run + " /dev/null"));
    ASSERT_EQ(sim.exit_code, 0) << sim.err;
    for (const auto& [name, command] : {std::pair{"E", bin("coolgas-energy") + " " + run},
                                        std::pair{"nm", bin("coolgas-clusters") + " " + run},
                                        std::pair{"fit", bin("coolgas-energy") + " " + run + " | " +
                                                             bin("coolgas-fit") + " --power --window 1:100 -"}}) {
      const auto r = run_command(command + " > " + *dir + "/" + name + ".tsv");
      ASSERT_EQ(r.exit_code, 0) << command << "\n" << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir; }
  static std::string table(const std::string& name) { return *dir + "/" + name + ".tsv"; }
  static std::string* dir;
};
std::string* TableReaders::dir = nullptr;

std::string joined(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& n : names) s += (s.empty() ? "" : ",") + n;
  return s;
}

// Each reader's line from tests/cli/read_tables.py against coolgas's reader.
void expect_python_readers_agree(const std::string& path) {
  const Table t = read_table(path);
  const auto r = run_command("/usr/bin/python3 " + test::source("tests/cli/read_tables.py") + " " + path);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  int readers = 0;
  for (std::string reader, names, last; lines >> reader >> names;) {
    std::size_t rows = 0;
    lines >> rows >> last;
    ++readers;
    if (names != "-") {
      EXPECT_EQ(names, joined(t.columns)) << reader << " on " << path;
    }
    EXPECT_EQ(rows, t.rows.size()) << reader << " on " << path;  // no row lost to a header
    EXPECT_NEAR(std::stod(last), t.rows.back()[0], 1e-15 * std::abs(t.rows.back()[0])) << reader;
  }
  EXPECT_EQ(readers, 3) << r.out;
}

// Points gnuplot reads with `using SPEC` (its `set table` output, one line per point).
std::size_t gnuplot_points(const std::string& path, const std::string& spec) {
  const std::string out = path + ".gnuplot";
  const auto r = run_command("gnuplot -e \"set table '" + out + "'; plot '" + path + "' using " + spec + "\"");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, "") << spec;  // e.g. 'warning: no column with header "t"'
  const auto count = run_command("grep -c ' i$' " + out);
  return std::stoul(count.out.empty() ? "0" : count.out);
}

TEST_F(TableReaders, PandasAndNumpyGetTheNamesAndEveryRow) {
  for (const char* name : {"E", "nm", "fit"}) expect_python_readers_agree(table(name));
}

TEST_F(TableReaders, GnuplotReadsByColumnNameAndNumber) {
  const std::size_t rows = read_table(table("E")).rows.size();
  EXPECT_EQ(gnuplot_points(table("E"), "'t':'E'"), rows);
  EXPECT_EQ(gnuplot_points(table("E"), "1:2"), rows);  // the column line is skipped, not a point
  const std::size_t nm_rows = read_table(table("nm")).rows.size();
  EXPECT_EQ(gnuplot_points(table("nm"), "'m':'N'"), nm_rows);  // every block
  EXPECT_EQ(gnuplot_points(table("nm"), "2:4"), nm_rows);
}

}  // namespace
}  // namespace coolgas
