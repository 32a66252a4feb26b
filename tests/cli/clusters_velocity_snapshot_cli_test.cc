// coolgas-clusters, coolgas-velocity and coolgas-snapshot run as a user
// would: they read files written by the real H5MD writer, their --help states
// units, and every bad input (empty file, wrong file type, missing datasets,
// NaN, bad option, missing or failing gnuplot) gives exactly one error line,
// exit code 2 and no half table.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>

#include "common/trajectory/h5md_writer.h"
#include "common/hdf5_file.h"
#include "common/random.h"
#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/gas_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;
using test::expect_one_error_line;
using test::run_command;

const char* const kTools[] = {"coolgas-clusters", "coolgas-velocity", "coolgas-snapshot"};

// Arguments that make each tool read `file` and otherwise succeed.
std::string command(const std::string& tool, const std::string& file, const std::string& dir) {
  std::string c = bin(tool) + " " + file;
  if (tool == "coolgas-snapshot") c += " --time 0 -o " + dir + "/out.png";
  return c;
}

class ClustersVelocitySnapshotCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("clusters_velocity_snapshot_cli"));
    test::write_gas_file(*dir + "/run.h5");
    test::write_gas_file(*dir + "/nan_position.h5", true, false);
    test::write_gas_file(*dir + "/nan_velocity.h5", false, true);
    std::ofstream(*dir + "/empty.h5");
    std::ofstream(*dir + "/table.tsv") << "# t\tE\n0\t1\n";
    // An HDF5 file with the H5MD root group but no particles.
    h5::Handle f = h5::open_file(*dir + "/no_particles.h5", h5::Mode::kCreateTruncate);
    h5::create_group(f.id(), "h5md");
  }
  static inline std::string* dir = nullptr;
};

TEST_F(ClustersVelocitySnapshotCli, EveryToolRejectsBadFilesWithOneLine) {
  for (const std::string tool : kTools) {
    SCOPED_TRACE(tool);
    expect_one_error_line(run_command(command(tool, *dir + "/empty.h5", *dir)), "cannot open");
    expect_one_error_line(run_command(command(tool, *dir + "/table.tsv", *dir)), "not HDF5");
    expect_one_error_line(run_command(command(tool, *dir + "/absent.h5", *dir)), "cannot open");
    const std::string missing =
        tool == "coolgas-velocity" ? "missing /particles/all/velocity" : "missing /particles/all/position";
    expect_one_error_line(run_command(command(tool, *dir + "/no_particles.h5", *dir)), missing);
  }
}

TEST_F(ClustersVelocitySnapshotCli, NaNInADumpIsOneErrorLineNamingDumpAndParticle) {
  expect_one_error_line(run_command(bin("coolgas-clusters") + " " + *dir + "/nan_position.h5"), "particle 17");
  expect_one_error_line(run_command(bin("coolgas-velocity") + " " + *dir + "/nan_velocity.h5"), "particle 5");
  expect_one_error_line(
      run_command(bin("coolgas-snapshot") + " " + *dir + "/nan_position.h5 --time 10 -o " + *dir + "/nan.png"),
      "non-finite");
  EXPECT_FALSE(std::filesystem::exists(*dir + "/nan.png"));
}

TEST_F(ClustersVelocitySnapshotCli, BadOptionsAreOneErrorLine) {
  const std::string run = *dir + "/run.h5";
  expect_one_error_line(run_command(bin("coolgas-clusters") + " " + run + " --bins-per-decade 0"), "bins");
  expect_one_error_line(run_command(bin("coolgas-clusters") + " " + run + " --no-such-option"), "no-such-option");
  expect_one_error_line(run_command(bin("coolgas-velocity") + " " + run + " --bins 7"), "--bins");
  // --tail needs the fit; --series keeps the row with beta NaN (tests/cli/conventions_cli_test.cc)
  expect_one_error_line(run_command(bin("coolgas-velocity") + " " + run + " --tail --tail-from 5.9"), "tail bins");
  expect_one_error_line(
      run_command(bin("coolgas-snapshot") + " " + run + " --time 0 -o " + *dir + "/x.png --colored 12"), "--colored");
  expect_one_error_line(run_command(bin("coolgas-snapshot") + " " + run + " --time 0 -o " + *dir + "/no/dir/x.png"),
                        "no directory");
}

TEST_F(ClustersVelocitySnapshotCli, HelpStatesUnits) {
  for (const std::string tool : kTools) {
    const auto r = run_command(bin(tool) + " --help");
    EXPECT_EQ(r.exit_code, 0) << tool;
    EXPECT_NE(r.out.find("[1/omega0]"), std::string::npos) << tool << " --help names no time unit";
    EXPECT_NE(r.out.find("sigma"), std::string::npos) << tool << " --help names no length or velocity unit";
  }
}

// 3000 particles in 25^3 cells, about one per five cells: the masses add up
// to N in every dump, whatever the clusters.
TEST_F(ClustersVelocitySnapshotCli, ClusterSeriesCountsEveryParticle) {
  const auto r = run_command(bin("coolgas-clusters") + " --series " + *dir + "/run.h5");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  const Table table = read_table(in, "stdout");
  for (double m1 : table.column_values("M1")) EXPECT_NEAR(m1 * 25 * 25 * 25, 3000, 1e-9);  // M1 V = N
  EXPECT_EQ(table.rows.size(), 2u);
}

TEST_F(ClustersVelocitySnapshotCli, SnapshotWritesAPngAndItsLegend) {
  const std::string png = *dir + "/snap.png";
  const auto r = run_command(bin("coolgas-snapshot") + " " + *dir + "/run.h5 --time 9 --colored 3 -o " + png);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream f(png, std::ios::binary);
  char magic[8] = {};
  f.read(magic, 8);
  EXPECT_EQ(std::string(magic + 1, 3), "PNG");
  EXPECT_NE(r.out.find("# dump_time: 10"), std::string::npos) << r.out;    // the dump nearest t = 9
  std::istringstream legend(r.out);
  EXPECT_EQ(read_table(legend, "stdout").rows.size(), 3u);  // one row per coloured cluster
}

TEST_F(ClustersVelocitySnapshotCli, SnapshotReportsMissingOrFailingGnuplot) {
  const std::string run = *dir + "/run.h5", png = *dir + "/never.png";
  expect_one_error_line(
      run_command(bin("coolgas-snapshot") + " " + run + " --time 0 -o " + png + " --gnuplot /nonexistent/gnuplot"),
      "install the gnuplot package");
  expect_one_error_line(run_command(bin("coolgas-snapshot") + " " + run + " --time 0 -o " + png + " --gnuplot false"),
                        "failed with exit code 1");
  EXPECT_FALSE(std::filesystem::exists(png));
}

}  // namespace
}  // namespace coolgas
