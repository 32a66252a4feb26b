// Rough particles (collision.beta, system.inertia) as a user runs them: the
// keys refused where they mean nothing, in one line; a rough run validates
// (schema version 5) and resumes bit for bit after a kill, spins included;
// coolgas-energy reports both temperatures and coolgas-velocity --spins the
// spins' statistics; a rough start from a file takes the file's spins, or
// draws them at T0 from a smooth file.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/hdf5_file.h"
#include "common/tsv.h"
#include "tests/support/killed_run.h"
#include "tests/support/one_run_suite.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::run_command;
using test::simulate;

// A small rough inelastic gas, a fraction of a second.
constexpr const char* kRoughScene = R"([system]
N = 1000
phi = 0.1
seed = 5
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.8
beta = 0.4
[run]
t_end = 50
[output]
dumps_per_decade = 10
)";

TEST(RoughCli, KeysWhereTheyMeanNothingAreRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("rough_bad_input");
  const std::string scene = test::write_file(dir, "rough.toml", kRoughScene), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " ";
  test::expect_simulate_refused(base + "--set collision.beta=2", "collision.beta = 2 is out of range", out);
  test::expect_simulate_refused(base + "--set system.dimension=1", "rods (system.dimension = 1) cannot spin", out);
  test::expect_simulate_refused(base + "--set system.inertia=0.9", "at most 0.6666666666666666", out);
  test::expect_simulate_refused(base + "--set collision.beta=-1 --set system.inertia=0.3",
                                "system.inertia is set but the particles are smooth", out);
}

class RoughRun : public test::OneRunSuite<RoughRun> {
 public:
  static constexpr const char* kFolder = "rough_run";
  static constexpr const char* kScene = kRoughScene;

 protected:
  // The same scene's smooth run (beta = -1) into `name`, briefly.
  static std::string smooth_run(const std::string& name) {
    std::string out = dir_ + "/" + name;
    const auto r = run_command(simulate(scene_ + " -o " + out + " --set collision.beta=-1 --set run.t_end=1"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }
};

TEST_F(RoughRun, ValidatesAsSchemaVersion5) {
  const auto v = run_command(test::bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("profile v5"), std::string::npos) << v.out;
}

TEST_F(RoughRun, KilledItResumesBitForBitSpinsIncluded) {
  const std::string out = dir_ + "/killed.h5";
  test::expect_killed_run_resumes_bit_for_bit(simulate(scene_ + " -o " + out), out, whole());
}

// The energy table's temperatures at t = 0 are T0 exactly (the start scales
// velocities and spins to it), each per axis; a smooth run's table has no such column.
TEST_F(RoughRun, TheEnergyTableHasBothTemperatures) {
  const auto r = run_command(test::bin("coolgas-energy") + " " + whole());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  const Table t = read_table(in, "energy");
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  const double T0 = h5::read_attr_double(h5::open_group(f.id(), "parameters").id(), "T0");
  ASSERT_EQ(t.column_values("t").at(0), 0.0);
  EXPECT_NEAR(t.column_values("T_tr").at(0) / T0, 1.0, 1e-12);
  EXPECT_NEAR(t.column_values("T_rot").at(0) / T0, 1.0, 1e-12);
  EXPECT_LT(t.column_values("T_rot").back(), 0.5 * T0);  // the gas cooled, spins too
}

// The spins at t = 0 are Maxwellian: kappa (against the 3-component
// Maxwellian) within 4 of its standard errors of 0. A smooth run has no spins.
TEST_F(RoughRun, TheVelocityToolTakesTheSpins) {
  const auto r = run_command(test::bin("coolgas-velocity") + " --series --spins --time 0 " + whole());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  const Table t = read_table(in, "velocity");
  EXPECT_LT(std::fabs(t.column_values("kappa").at(0)), 4 * t.column_values("kappa_err").at(0));
  const std::string smooth = smooth_run("smooth.h5");
  test::expect_refused_with_one_line(run_command(test::bin("coolgas-velocity") + " --spins " + smooth),
                                     "no angular velocities", "coolgas-velocity --spins SMOOTH");
}

// A rough start from the rough file takes its last dump's spins; from a
// smooth file it draws them at T0 (rotational energy (d_r/2) T0 = 1.5 T0).
TEST_F(RoughRun, AStartFromAFileTakesItsSpinsOrDrawsThem) {
  const std::string next = dir_ + "/next.h5", drawn = dir_ + "/drawn.h5";
  const std::string from = "--set system.init=file --set system.equilibrate=5 --set run.t_end=1 --set system.from=";
  ASSERT_EQ(run_command(simulate(scene_ + " -o " + next + " " + from + whole())).exit_code, 0);
  h5::Handle a = h5::open_file(whole(), h5::Mode::kReadOnly), b = h5::open_file(next, h5::Mode::kReadOnly);
  const auto last = h5::shape(h5::open_dataset(a.id(), "particles/all/angular_velocity/value").id())[0] - 1;
  EXPECT_EQ(h5::read_row<double>(h5::open_dataset(a.id(), "particles/all/angular_velocity/value").id(), last),
            h5::read_row<double>(h5::open_dataset(b.id(), "particles/all/angular_velocity/value").id(), 0));
  ASSERT_EQ(run_command(simulate(scene_ + " -o " + drawn + " " + from + smooth_run("smooth_start.h5"))).exit_code, 0);
  h5::Handle c = h5::open_file(drawn, h5::Mode::kReadOnly);
  const double T0 = h5::read_attr_double(h5::open_group(c.id(), "parameters").id(), "T0");
  const double E_rot =
      h5::read_row<double>(h5::open_dataset(c.id(), "observables/rotational_energy/value").id(), 0).at(0);
  EXPECT_NEAR(E_rot / (1.5 * T0), 1.0, 1e-12);
}

// coolgas-convert writes the spins (extended XYZ omega:R:3, LAMMPS's
// omegax omegay omegaz), and a rough start from the XYZ frame takes them:
// its first dump's spins are the last dump's, bit for bit.
TEST_F(RoughRun, TheSpinsGoThroughAnXyzFrame) {
  const std::string xyz = dir_ + "/last.xyz", next = dir_ + "/from_xyz.h5";
  ASSERT_EQ(run_command(test::bin("coolgas-convert") + " --last " + whole() + " > " + xyz).exit_code, 0);
  const std::string from = "--set system.init=file --set system.equilibrate=5 --set run.t_end=1 --set system.from=";
  const auto r = run_command(simulate(scene_ + " -o " + next + " " + from + xyz));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  h5::Handle a = h5::open_file(whole(), h5::Mode::kReadOnly), b = h5::open_file(next, h5::Mode::kReadOnly);
  const auto last = h5::shape(h5::open_dataset(a.id(), "particles/all/angular_velocity/value").id())[0] - 1;
  EXPECT_EQ(h5::read_row<double>(h5::open_dataset(a.id(), "particles/all/angular_velocity/value").id(), last),
            h5::read_row<double>(h5::open_dataset(b.id(), "particles/all/angular_velocity/value").id(), 0));
  const auto dump = run_command(test::bin("coolgas-convert") + " --format lammps --last " + whole());
  ASSERT_EQ(dump.exit_code, 0) << dump.err;
  EXPECT_NE(dump.out.find("ITEM: ATOMS id type x y z vx vy vz ix iy iz omegax omegay omegaz\n"), std::string::npos);
}

}  // namespace
}  // namespace coolgas
