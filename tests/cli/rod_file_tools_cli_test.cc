// The analysis tools on a 1D file (rods on a ring), driven as a user would,
// on a file from the H5MD writer itself, made to order (a run of the
// simulator is tests/cli/rod_tools_cli_test.cc): 2000 rods uniform on a ring
// of 400 with Gaussian velocities at T0 = 1, and an energy that leaves
// Haff's law for the 1D theories' t^(-2/3) well before the crossover, which
// a short simulated run does not.
// Each table says `# dimension: 1` and holds the 1D numbers (densities per
// sigma, one velocity component, n grid points, R_g alone); each bad
// combination (1D and 3D runs in one ensemble or one collapse, an option of
// the 2D and 3D pictures, a LAMMPS dump) is one error line and a non-zero
// exit.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/random.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/energy_test_runs.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;

constexpr int kRods = 2000;
constexpr double kRing = 400;

// E per rod: (d/2) T0 = 1/2 at t = 0, Haff's (1 + t)^-2 to t = 20, then t^(-2/3).
double rod_energy(double t) {
  const double haff = 0.5 / ((1 + t) * (1 + t));
  return t <= 20 ? haff : 0.5 / (21.0 * 21.0) * std::pow(t / 20, -2.0 / 3.0);
}

// Observations at t = 0 and 10^(k/10) up to 10^4, dumps at t = 0, 100 and
// 10^4 (each its own draw, velocities at the energy of its time).
void write_rod_file(const std::string& path) {
  RunParameters p;
  p.N = kRods;
  p.L = kRing;
  p.T0 = 1;
  p.seed = 3;
  H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(1));
  Random rng(3);
  std::vector<double> pos(3 * kRods), vel(3 * kRods);
  const std::vector<std::int32_t> img(3 * kRods, 0);
  for (int k = -1; k <= 40; ++k) {
    const double t = k < 0 ? 0.0 : std::pow(10.0, k / 10.0);
    w.add_observables({t, k + 1, 0, rod_energy(t), {0, 0, 0}});
    if (k >= 0 && k != 20 && k != 40) continue;
    for (double& x : pos) x = kRing * rng.uniform();
    for (double& v : vel) v = std::sqrt(2 * rod_energy(t)) * rng.normal();
    w.add_frame({t, k + 1, 0, pos.data(), img.data(), vel.data()});
  }
}

class RodFileToolsCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("rod_file_tools_cli"));
    write_rod_file(rods());
    // The same run as 3D spheres: only the dimension differs.
    RunParameters p;
    p.N = kRods;
    p.L = kRing;
    p.T0 = 1;
    p.seed = 4;
    test::write_energy_run(spheres(), p, {0, 1, 10, 100}, rod_energy, Geometry(3));
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string rods() { return *dir_ + "/rods.h5"; }
  static std::string spheres() { return *dir_ + "/spheres.h5"; }
  static Table table(const std::string& command) {
    const auto r = run_command(command);
    EXPECT_EQ(r.exit_code, 0) << command << "\n" << r.err;
    std::istringstream in(r.out);
    return read_table(in, command);
  }
  static inline std::string* dir_ = nullptr;
};

// E(0) = (d/2) T0 = T0/2 per rod; a 1D run and a 3D one are not averaged.
TEST_F(RodFileToolsCli, EnergyOfA1DFileSaysItsDimension) {
  const Table e = table(bin("coolgas-energy") + " " + rods());
  EXPECT_EQ(e.get("dimension"), "1");
  ASSERT_EQ(e.rows.at(0)[e.column("t")], 0.0);
  EXPECT_EQ(e.rows[0][e.column("E")], 0.5);
  test::expect_one_error_line(run_command(bin("coolgas-energy") + " " + rods() + " " + spheres()),
                              "dimension = 1 vs 3");
}

// The fit's default window ends at the 1D crossover 0.1 L^(3/2) = 800 and
// finds about the t^(-2/3) put in past Haff's law; collapse keeps 1D to
// itself.
TEST_F(RodFileToolsCli, FitAndCollapseUseTheOneDimensionalScaling) {
  const std::string e1 = *dir_ + "/e1.tsv", e3 = *dir_ + "/e3.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + rods() + " > " + e1).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + spheres() + " > " + e3).exit_code, 0);
  const auto fit = run_command(bin("coolgas-fit") + " --power " + e1);
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  EXPECT_NE(fit.err.find("0.1 L^(3/2), L = 400)"), std::string::npos) << fit.err;
  EXPECT_NE(fit.err.find(" to 800 "), std::string::npos) << fit.err;
  std::istringstream in(fit.out);
  const Table f = read_table(in, "fit");
  const auto& r = f.rows.at(0);
  EXPECT_LE(r[f.column("t_max")], 800);
  EXPECT_GT(r[f.column("t_max")], 700);  // the last row of 20 per decade below 800
  EXPECT_NEAR(r[f.column("theta")], 2.0 / 3.0, 0.05) << fit.out;  // the window's start takes in a Haff point
  test::expect_one_error_line(run_command(bin("coolgas-collapse") + " " + e1 + " " + e3),
                              "tables of different dimensions cannot be collapsed together");
}

// Unit segments: M1 is the line density N/L exactly.
TEST_F(RodFileToolsCli, ClustersAreOfUnitSegmentsPerUnitLength) {
  const Table s = table(bin("coolgas-clusters") + " --series " + rods());
  EXPECT_EQ(s.get("dimension"), "1");
  ASSERT_EQ(s.rows.size(), 3u);
  for (const auto& row : s.rows) EXPECT_NEAR(row[s.column("M1")], kRods / kRing, 1e-12);
}

// Gaussian velocities: kappa against the 1D Maxwellian's 3 is 0 within 4 errors.
TEST_F(RodFileToolsCli, VelocityIsOneComponentWithTheOneDimensionalReference) {
  const Table v = table(bin("coolgas-velocity") + " --series " + rods());
  EXPECT_EQ(v.get("dimension"), "1");
  for (const auto& row : v.rows)
    EXPECT_LT(std::abs(row[v.column("kappa")]), 4 * row[v.column("kappa_err")]) << row[v.column("t")];
}

TEST_F(RodFileToolsCli, StructureAndShapeHaveTheirOneDimensionalColumns) {
  const Table s = table(bin("coolgas-structure") + " --time 100 " + rods());
  EXPECT_EQ(s.get("dimension"), "1");
  EXPECT_EQ(s.get("grid"), "400 points on the ring, spacing 1 sigma");
  EXPECT_EQ(s.rows.size(), 100u);  // shells 1 .. n/4
  const Table c = table(bin("coolgas-shape") + " --clusters " + rods());
  EXPECT_EQ(c.columns, (std::vector<std::string>{"t", "mass", "Rg", "lambda1", "wraps"}));
  EXPECT_EQ(table(bin("coolgas-shape") + " --series " + rods()).columns.size(), 6u);
}

TEST_F(RodFileToolsCli, SnapshotDrawsTheSpaceTimeDiagramAndRefusesThePictureOptions) {
  const std::string png = *dir_ + "/rods.png";
  const Table t = table(bin("coolgas-snapshot") + " " + rods() + " --time 100 --force -o " + png);
  EXPECT_EQ(t.get("view"), "space-time");
  EXPECT_EQ(t.rows.size(), 2u);  // the dumps at t = 0 and 100
  for (const char* option : {"--view 3d", "--thickness 2", "--colored 3", "--max-points 10"})
    test::expect_one_error_line(
        run_command(bin("coolgas-snapshot") + " " + rods() + " --time 100 --force " + option + " -o " + png),
        std::string(option) + " is not for 1D trajectories (rods)");
}

}  // namespace
}  // namespace coolgas
