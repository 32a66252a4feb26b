// The analysis tools on a 1D run of coolgas-simulate (hard rods on a ring),
// driven as a user would: each table says `# dimension: 1` and holds the 1D
// physics (E(0) = T0/2, densities per sigma, one velocity component against
// the 1D Maxwellian's kurtosis, n grid points where the equilibrium hard-rod
// gas has S(k -> 0) = (1 - phi)^2, R_g-only shapes, a space-time picture,
// an XYZ cell periodic along x), and each bad combination — 1D and 3D runs
// in one ensemble or one collapse, an option of the 2D and 3D pictures for a
// 1D file, a LAMMPS dump of it — is one error line.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;
using test::simulate;

// The cooling gas of tests/support/simulate_cli.h as 4000 rods at line
// fraction 0.2 to t = 30, and as 500 spheres to t = 10.
const char* kRodRun =
    " --set system.dimension=1 --set system.N=4000 --set system.seed=7 --set run.t_end=30"
    " --set output.dumps_per_decade=5";
const char* kSphereRun = " --set system.N=500 --set run.t_end=10";

class RodToolsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("rod_tools_cli"));
    const std::string scene = test::write_file(*dir_, "gas.toml", test::kCoolingGasScene);
    for (auto [set, out] : {std::pair{kRodRun, rods()}, {kSphereRun, spheres()}}) {
      const auto r = run_command(simulate(scene + set + " -o " + out));
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string rods() { return *dir_ + "/rods.h5"; }
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

// E(0) = (d/2) T0 per particle: T0/2 for rods.
TEST_F(RodToolsCli, EnergyOfA1DRunSaysItsDimension) {
  const Table e = table(bin("coolgas-energy") + " " + rods());
  EXPECT_EQ(e.get("dimension"), "1");
  ASSERT_EQ(e.rows.at(0)[e.column("t")], 0.0);
  const double T0 = std::stod(*e.get("T0"));
  EXPECT_NEAR(e.rows[0][e.column("E")], T0 / 2, 1e-12 * T0);
  test::expect_one_error_line(run_command(bin("coolgas-energy") + " " + rods() + " " + spheres()),
                              "dimension = 1 vs 3");
}

// The fit's default window ends at the 1D crossover 0.1 L^z, z = (d+2)/2 =
// 3/2 (this short run is still in Haff's law there, which the fit says).
TEST_F(RodToolsCli, FitAndCollapseUseTheOneDimensionalScaling) {
  const std::string e1 = *dir_ + "/e1.tsv", e3 = *dir_ + "/e3.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + rods() + " > " + e1).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + spheres() + " > " + e3).exit_code, 0);
  const auto fit = run_command(bin("coolgas-fit") + " --power " + e1);
  EXPECT_NE(fit.err.find("0.1 L^(3/2)"), std::string::npos) << fit.err;
  EXPECT_EQ(fit.err.find("L^(5/2)"), std::string::npos) << fit.err;
  const Table c = table(bin("coolgas-collapse") + " --theta 0.6667 --z 1.5 " + e1);
  EXPECT_EQ(c.get("dimension"), "1");
  test::expect_one_error_line(run_command(bin("coolgas-collapse") + " " + e1 + " " + e3),
                              "tables of different dimensions cannot be collapsed together");
}

// Unit segments: M1 is the line density N/L exactly.
TEST_F(RodToolsCli, ClustersOfA1DRunArePerUnitLength) {
  const Table s = table(bin("coolgas-clusters") + " --series " + rods());
  EXPECT_EQ(s.get("dimension"), "1");
  EXPECT_NE(s.get("cells")->find("floor(L) segments"), std::string::npos);
  const double L = std::stod(*s.get("L"));
  for (const auto& row : s.rows) {
    EXPECT_NEAR(row[s.column("M1")], 4000 / L, 1e-12);
    EXPECT_LE(row[s.column("largest_fraction")], 1.0);
    EXPECT_GE(row[s.column("M_avg")], 1.0);
  }
}

// The equilibrium start is a 1D Maxwellian: kappa = <v^4>/<v^2>^2 - 3 is 0
// within its error sqrt(24/N) (the 3D reference, 5/3, would give 4/3 = 17
// errors away).
TEST_F(RodToolsCli, VelocityOfA1DStartIsMaxwellianInOneDimension) {
  const Table v = table(bin("coolgas-velocity") + " --series --time 0 --exact-time " + rods());
  EXPECT_EQ(v.get("dimension"), "1");
  ASSERT_EQ(v.rows.size(), 1u);
  const double kappa = v.rows[0][v.column("kappa")], err = v.rows[0][v.column("kappa_err")];
  EXPECT_NEAR(err, std::sqrt(24.0 / 4000), 0.2 * std::sqrt(24.0 / 4000));
  EXPECT_LT(std::abs(kappa), 4 * err) << kappa << " +- " << err;
}

// Hard rods at line fraction phi: S(k -> 0) = (1 - phi)^2 = 0.64 (Tonks), a
// gas far less compressible than an ideal one; the 256 shells of the ring's
// grid reach k = 0.08 only, where S is still that, each one mode
// (exponential, S_err = S): their mean within 4 errors 0.64/16.
TEST_F(RodToolsCli, StructureOfA1DStartIsTheHardRodGas) {
  const Table s = table(bin("coolgas-structure") + " --time 0 --exact-time " + rods());
  EXPECT_EQ(s.get("dimension"), "1");
  EXPECT_NE(s.get("grid")->find(" points on the ring"), std::string::npos);
  ASSERT_EQ(s.rows.size(), 256u);
  double sum = 0;
  for (const auto& row : s.rows) {
    EXPECT_EQ(row[s.column("modes")], 1);
    sum += row[s.column("S")];
  }
  EXPECT_NEAR(sum / 256, 0.64, 4 * 0.64 / 16);
}

TEST_F(RodToolsCli, ShapesOfA1DRunAreTheRadiusOfGyrationAlone) {
  const Table c = table(bin("coolgas-shape") + " --clusters --min-mass 5 " + rods());
  EXPECT_EQ(c.get("dimension"), "1");
  EXPECT_EQ(c.columns, (std::vector<std::string>{"t", "mass", "Rg", "lambda1", "wraps"}));
  ASSERT_GT(c.rows.size(), 10u);
  for (const auto& row : c.rows) {
    const double Rg = row[c.column("Rg")];
    EXPECT_NEAR(Rg * Rg, row[c.column("lambda1")], 1e-9 * Rg * Rg);
  }
}

TEST_F(RodToolsCli, SnapshotDrawsTheSpaceTimeDiagramAndRefusesThePictureOptions) {
  const std::string png = *dir_ + "/rods.png";
  const Table t = table(bin("coolgas-snapshot") + " " + rods() + " --time 30 --force -o " + png);
  EXPECT_EQ(t.get("view"), "space-time");
  ASSERT_GT(t.rows.size(), 5u);  // the dumps up to t = 30
  for (const auto& row : t.rows) EXPECT_EQ(row[t.column("particles")], 4000);
  EXPECT_LT(t.rows.back()[t.column("v_rms")], t.rows.front()[t.column("v_rms")]);  // the gas cools
  for (const char* option : {"--view slab", "--thickness 2", "--colored 3", "--max-points 10"})
    test::expect_one_error_line(
        run_command(bin("coolgas-snapshot") + " " + rods() + " --time 30 --force " + option + " -o " + png),
        std::string(option) + " is not for 1D trajectories (rods)");
}

// ASE reads the XYZ as a cell (L, 1, 1) periodic along x (tests/cli/read_exports.py); no LAMMPS dump.
TEST_F(RodToolsCli, ConvertWritesXyzOnly) {
  const std::string xyz = *dir_ + "/rods.xyz";
  ASSERT_EQ(run_command(bin("coolgas-convert") + " " + rods() + " > " + xyz).exit_code, 0);
  const auto a = run_command("/usr/bin/python3 " + test::source("tests/cli/read_exports.py") + " xyz " + rods() + " " + xyz);
  EXPECT_EQ(a.exit_code, 0) << a.out << a.err;
  test::expect_one_error_line(run_command(bin("coolgas-convert") + " --format lammps " + rods()),
                              "has no LAMMPS dump");
}

}  // namespace
}  // namespace coolgas
