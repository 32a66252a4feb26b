// The driven gas ([driving], simulate/engine/driving.h) as a user runs it:
// bad driving keys are refused with one line; a driven run records its
// power and period in /parameters (schema version 4) and validates; a run
// without [driving] writes no trace of it; a driven run stopped at named
// points (killed after K events, SIGINT, killed amid a dump) resumes to the
// uninterrupted run's file bit for bit; a resume cannot change the driving.
#include <gtest/gtest.h>

#include <string>

#include "common/hdf5_file.h"
#include "tests/support/fault_points.h"
#include "tests/support/one_run_suite.h"
#include "tests/support/run_command.h"
#include "tests/support/same_trajectory.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::run_command;
using test::simulate;

// A small driven inelastic gas near its steady state, a fraction of a second.
constexpr const char* kDrivenScene = R"([system]
N = 1000
phi = 0.1
seed = 4
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.7
[driving]
power = 0.02
period = 0.25
[run]
t_end = 100
[output]
dumps_per_decade = 10
)";

TEST(DrivingCli, BadDrivingIsRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("driving_bad_input");
  const std::string scene = test::write_file(dir, "driven.toml", kDrivenScene), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " ";
  for (const char* power : {"0", "-1", "nan", "inf"})
    test::expect_simulate_refused(base + "--set driving.power=" + power, "driving.power", out);
  for (const char* period : {"0", "0.001", "11"})
    test::expect_simulate_refused(base + "--set driving.period=" + period, "driving.period", out);
  test::expect_simulate_refused(base + "--set driving.powr=1", "did you mean 'driving.power'", out);
  test::expect_simulate_refused(base + "--set collision.model=aggregation --set collision.r0=1", "driving.power",
                                out);
  const std::string undriven = test::write_file(dir, "undriven.toml", test::kCoolingGasScene);
  test::expect_simulate_refused(undriven + " -o " + out + " --set driving.period=1", "driving.power", out);
}

struct Parameters {
  std::int64_t schema_version;
  bool driven;
  double power = 0, period = 0;
};
Parameters parameters_of(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle g = h5::open_group(f.id(), "parameters");
  Parameters p{h5::read_attr_int(g.id(), "schema_version"), h5::has_attr(g.id(), "driving_power")};
  if (p.driven) {
    p.power = h5::read_attr_double(g.id(), "driving_power");
    p.period = h5::read_attr_double(g.id(), "driving_period");
  }
  return p;
}

class DrivingResume : public test::OneRunSuite<DrivingResume> {
 public:
  static constexpr const char* kFolder = "driving_resume";
  static constexpr const char* kScene = kDrivenScene;
  static void after_run() { collisions_ = test::collisions_of(whole()); }

 protected:
  // Runs the scene into `name` with the fault `spec` armed (a checkpoint
  // after every slice of events), expecting `exit_code`, then resumes it.
  static std::string stop_and_resume(const std::string& name, const std::string& spec, int exit_code) {
    std::string out = dir_ + "/" + name + ".h5";
    const auto stopped =
        run_command("COOLGAS_CHECKPOINT_INTERVAL=0 " + test::fault(spec) + simulate(scene_ + " -o " + out));
    EXPECT_EQ(stopped.exit_code, exit_code) << spec << ": " << stopped.err;
    const auto resumed = run_command(simulate("--resume " + out));
    EXPECT_EQ(resumed.exit_code, 0) << spec << ": " << resumed.err;
    return out;
  }
  static inline std::int64_t collisions_ = 0;
};

TEST_F(DrivingResume, TheFileRecordsTheDrivingAndValidates) {
  const Parameters p = parameters_of(whole());
  EXPECT_EQ(p.schema_version, 4);
  EXPECT_TRUE(p.driven);
  EXPECT_EQ(p.power, 0.02);
  EXPECT_EQ(p.period, 0.25);
  const auto v = run_command(test::bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("profile v4"), std::string::npos) << v.out;
  // Without [driving], nothing of it: the inelastic model's version 1, no attribute, no table in the scene.
  const std::string plain = dir_ + "/plain.h5";
  const std::string undriven = test::write_file(dir_, "undriven.toml", test::kCoolingGasScene);
  ASSERT_EQ(run_command(simulate(undriven + " -o " + plain + " --set system.N=300 --set run.t_end=5")).exit_code, 0);
  const Parameters q = parameters_of(plain);
  EXPECT_EQ(q.schema_version, 1);
  EXPECT_FALSE(q.driven);
  h5::Handle f = h5::open_file(plain, h5::Mode::kReadOnly);
  EXPECT_EQ(h5::read_attr_string(h5::open_group(f.id(), "parameters").id(), "scene").find("driving"),
            std::string::npos);
}

TEST_F(DrivingResume, KilledAfterKEventsItResumesBitForBit) {
  test::expect_same_trajectory(whole(), stop_and_resume("killed", test::events_at(0.4, collisions_), test::kKilled));
}

TEST_F(DrivingResume, InterruptedItResumesBitForBit) {
  test::expect_same_trajectory(whole(), stop_and_resume("sigint", test::events_at(0.7, collisions_, "INT"), 3));
}

TEST_F(DrivingResume, KilledAmidADumpItResumesBitForBit) {
  test::expect_same_trajectory(whole(), stop_and_resume("dump", "dump-frame:12", test::kKilled));
}

TEST_F(DrivingResume, AResumeCannotChangeTheDriving) {
  const std::string out = dir_ + "/changed.h5";
  ASSERT_EQ(run_command(simulate(scene_ + " -o " + out + " --set run.t_end=5")).exit_code, 0);
  test::expect_refused_with_one_line(run_command(simulate("--resume " + out + " --set driving.power=0.04")),
                                     "driving.power", "--resume --set driving.power");
}

}  // namespace
}  // namespace coolgas
