// The analysis tools on a 2D run of coolgas-simulate (hard disks), driven as
// a user would: each table says `# dimension: 2` and holds the 2D physics
// (densities per sigma^2, two velocity components with the 2D Maxwellian's
// kurtosis reference, n^2 grids), and each bad combination — 2D and 3D runs
// in one ensemble or one collapse, a 3D-only option for a 2D file — is one
// error line. A 3D table carries no dimension line.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;
using test::simulate;

// The cooling gas of tests/support/simulate_cli.h as 4000 disks at area
// fraction 0.3 to t = 100, and as 500 spheres to t = 10.
const char* kDisks =
    " --set system.dimension=2 --set system.N=4000 --set system.phi=0.3 --set system.seed=7 --set run.t_end=100"
    " --set output.dumps_per_decade=5";
const char* kSpheres = " --set system.N=500 --set run.t_end=10";

class DiskToolsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("disk_tools_cli"));
    const std::string scene = test::write_file(*dir_, "gas.toml", test::kCoolingGasScene);
    for (auto [set, out] : {std::pair{kDisks, disks()}, {kSpheres, spheres()}}) {
      const auto r = run_command(simulate(scene + set + " -o " + out));
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string disks() { return *dir_ + "/disks.h5"; }
  static std::string spheres() { return *dir_ + "/spheres.h5"; }
  // A tool's table on stdout, read back; the test fails on a non-zero exit.
  static Table table(const std::string& command) {
    const auto r = run_command(command);
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.err;
    std::istringstream in(r.out);
    return read_table(in, command);
  }
  static inline std::string* dir_ = nullptr;
};

// E(0) = (d/2) T0 per particle, T0 the temperature per component: T0 for
// disks, (3/2) T0 for spheres.
TEST_F(DiskToolsCli, EnergyOfA2DRunSaysItsDimension) {
  const Table e = table(bin("coolgas-energy") + " " + disks()), s = table(bin("coolgas-energy") + " " + spheres());
  EXPECT_EQ(e.get("dimension"), "2");
  EXPECT_FALSE(s.get("dimension"));
  ASSERT_EQ(e.rows.at(0)[e.column("t")], 0.0);
  const double T0 = std::stod(*e.get("T0")), T0_3d = std::stod(*s.get("T0"));
  EXPECT_NEAR(e.rows[0][e.column("E")], T0, 1e-12 * T0);
  EXPECT_NEAR(s.rows.at(0)[s.column("E")], 1.5 * T0_3d, 1e-12 * T0_3d);
  test::expect_one_error_line(run_command(bin("coolgas-energy") + " " + disks() + " " + spheres()),
                              "dimension = 2 vs 3");
}

// The fit's default window ends at the 2D crossover 0.1 L^z, z = (d+2)/2 = 2.
TEST_F(DiskToolsCli, FitAndCollapseUseTheTwoDimensionalScaling) {
  const std::string e2 = *dir_ + "/e2.tsv", e3 = *dir_ + "/e3.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + disks() + " > " + e2).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + spheres() + " > " + e3).exit_code, 0);
  const auto fit = run_command(bin("coolgas-fit") + " --power " + e2);
  EXPECT_NE(fit.err.find("0.1 L^2"), std::string::npos) << fit.err;
  EXPECT_EQ(fit.err.find("L^(5/2)"), std::string::npos) << fit.err;
  const Table c = table(bin("coolgas-collapse") + " --theta 1 --z 2 " + e2);
  EXPECT_EQ(c.get("dimension"), "2");
  test::expect_one_error_line(run_command(bin("coolgas-collapse") + " " + e2 + " " + e3),
                              "tables of different dimensions cannot be collapsed together");
}

// Unit squares: M1 is the number density N/L^2 exactly, the masses sum to N.
TEST_F(DiskToolsCli, ClustersOfA2DRunArePerUnitArea) {
  const Table s = table(bin("coolgas-clusters") + " --series " + disks());
  EXPECT_EQ(s.get("dimension"), "2");
  EXPECT_NE(s.get("cells")->find("floor(L)^2 square cells"), std::string::npos);
  const double L = std::stod(*s.get("L"));
  for (const auto& row : s.rows) {
    EXPECT_NEAR(row[s.column("M1")], 4000 / (L * L), 1e-12);
    EXPECT_LE(row[s.column("largest_fraction")], 1.0);
    EXPECT_GE(row[s.column("M_avg")], 1.0);
  }
}

// The equilibrated start is a 2D Maxwellian: kappa = <v^4>/<v^2>^2 - 2 is 0
// within its error (the 3D reference, 5/3, would give 1/3 = 13 errors away).
TEST_F(DiskToolsCli, VelocityOfA2DStartIsMaxwellianInTwoDimensions) {
  const Table v = table(bin("coolgas-velocity") + " --series --time 0 --exact-time " + disks());
  EXPECT_EQ(v.get("dimension"), "2");
  ASSERT_EQ(v.rows.size(), 1u);
  const double kappa = v.rows[0][v.column("kappa")], err = v.rows[0][v.column("kappa_err")];
  EXPECT_NEAR(err, 2 / std::sqrt(4000.0), 0.3 * 2 / std::sqrt(4000.0));
  EXPECT_LT(std::abs(kappa), 4 * err) << kappa;
}

// Hard disks at phi = 0.3 are far less compressible than an ideal gas: the
// lowest shells of the start's S(k) lie well below 1 (S(0) = (1 - phi)^3 /
// (1 + phi) = 0.26 by scaled-particle theory).
TEST_F(DiskToolsCli, StructureOfA2DRunUsesASquareGrid) {
  const Table s = table(bin("coolgas-structure") + " --time 0 --exact-time " + disks());
  EXPECT_EQ(s.get("dimension"), "2");
  EXPECT_NE(s.get("grid")->find("^2 points"), std::string::npos);
  ASSERT_GE(s.rows.size(), 3u);
  for (int i = 0; i < 3; ++i) EXPECT_LT(s.rows[i][s.column("S")], 0.6) << "shell " << i + 1;
  const Table series = table(bin("coolgas-structure") + " --series " + disks());
  EXPECT_GT(series.rows.back()[series.column("L_t")], 0.0);
}

// Clusters of squares have a 2 x 2 gyration tensor: R_g^2 = lambda1 + lambda2,
// asphericity in [0, 1], and the 2D table has no lambda3 or prolateness.
TEST_F(DiskToolsCli, ShapesOfA2DRunAreTwoDimensional) {
  const Table c = table(bin("coolgas-shape") + " --clusters --min-mass 20 " + disks());
  EXPECT_EQ(c.get("dimension"), "2");
  EXPECT_EQ(c.columns, (std::vector<std::string>{"t", "mass", "Rg", "lambda1", "lambda2", "asphericity", "wraps"}));
  ASSERT_GT(c.rows.size(), 10u);
  for (const auto& row : c.rows) {
    if (row[c.column("wraps")] != 0) continue;
    const double Rg = row[c.column("Rg")];
    EXPECT_NEAR(Rg * Rg, row[c.column("lambda1")] + row[c.column("lambda2")], 1e-9 * Rg * Rg);
    EXPECT_GE(row[c.column("asphericity")], 0.0);
    EXPECT_LE(row[c.column("asphericity")], 1.0);
  }
  const Table s = table(bin("coolgas-shape") + " --series " + disks());
  EXPECT_EQ(s.columns.size(), 7u);
}

// MDAnalysis 2.4 reads 3D boxes only: it refuses a 2D file with its own
// ValueError (data-schema/h5md-profile.md says so; coolgas-convert's LAMMPS
// dump of the file is what it reads, tests/cli/convert_cli_test.cc).
TEST_F(DiskToolsCli, MDAnalysisRefusesA2DFile) {
  const auto r = run_command("/usr/bin/python3 " + test::source("tests/cli/read_exports.py") + " mda_2d " + disks() +
                             " 4000");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

TEST_F(DiskToolsCli, SnapshotDrawsThePlaneAndRefusesTheThreeDimensionalOptions) {
  const std::string png = *dir_ + "/disks.png";
  const Table legend = table(bin("coolgas-snapshot") + " " + disks() + " --time 100 --colored 3 --force -o " + png);
  EXPECT_EQ(legend.get("view"), "plane");
  EXPECT_EQ(legend.rows.size(), 3u);
  EXPECT_GT(test::read_text(png).size(), 1000u);
  test::expect_one_error_line(run_command(bin("coolgas-snapshot") + " " + disks() + " --time 100 --view 3d --force -o " + png),
                              "--view 3d is for 3D trajectories");
  test::expect_one_error_line(
      run_command(bin("coolgas-snapshot") + " " + disks() + " --time 100 --thickness 2 --force -o " + png),
      "--thickness 2 is for 3D trajectories");
}

}  // namespace
}  // namespace coolgas
