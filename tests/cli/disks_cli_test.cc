// coolgas-simulate with system.dimension = 2, driven as a user would: the
// file is H5MD with box/dimension = 2 and 2-component vectors, the
// validator accepts it, a run extended or stopped and resumed is bit for bit
// the uninterrupted one, and bad dimensions are one line each (the analysis
// tools on a 2D file: disk_tools_cli_test.cc).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "common/hdf5_file.h"
#include "tests/support/killed_run.h"
#include "tests/support/one_run_suite.h"
#include "tests/support/run_command.h"
#include "tests/support/same_trajectory.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;

// The resume tests' cooling gas as disks, to t = 300.
std::string disks(const std::string& args) {
  return test::simulate(args + " --set system.dimension=2 --set run.t_end=300");
}

class DisksCli : public test::OneRunSuite<DisksCli> {
 public:
  static constexpr const char* kFolder = "disks_cli";
  static constexpr const char* kScene = test::kCoolingGasScene;
  static std::string launch(const std::string& args) { return disks(args); }
};

TEST_F(DisksCli, TheFileIsA2DH5mdFileTheValidatorAccepts) {
  const auto v = run_command(bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  h5::Handle box = h5::open_group(f.id(), "particles/all/box");
  EXPECT_EQ(h5::read_attr_int(box.id(), "dimension"), 2);
  EXPECT_EQ(h5::read_attr_strings(box.id(), "boundary"), (std::vector<std::string>{"periodic", "periodic"}));
  for (const char* element : {"position", "velocity", "image"}) {
    h5::Handle d = h5::open_dataset(f.id(), std::string("particles/all/") + element + "/value");
    EXPECT_EQ(h5::shape(d.id()).at(2), 2u) << element;
  }
  h5::Handle edges = h5::open_dataset(f.id(), "particles/all/box/edges/value");
  EXPECT_EQ(h5::shape(edges.id()).at(1), 2u);
  h5::Handle p = h5::open_dataset(f.id(), "observables/total_momentum/value");
  EXPECT_EQ(h5::shape(p.id()).at(1), 2u);
}

TEST_F(DisksCli, AnExtendedRunIsBitForBitTheWholeOne) {
  const std::string out = dir_ + "/part.h5";
  const std::string part = test::simulate(scene_ + " -o " + out + " --set system.dimension=2 --set run.t_end=100");
  ASSERT_EQ(run_command(part).exit_code, 0);  // t = 100 is on the dump grid
  const auto r = run_command(test::simulate("--resume " + out + " --set run.t_end=300"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  test::expect_same_trajectory(whole(), out);
}

// Killed mid-run (halfway through the whole run's collisions, a checkpoint
// after every slice of events), resumed from its checkpoint.
TEST_F(DisksCli, AKilledRunResumesBitForBit) {
  const std::string out = dir_ + "/killed.h5";
  test::expect_killed_run_resumes_bit_for_bit(disks(scene_ + " -o " + out), out, whole());
}

TEST(DisksCliScene, BadDimensionsAreOneLineEach) {
  const std::string dir = test::scratch_dir("disks_bad_scene");
  const std::string scene = test::write_file(dir, "gas.toml", test::kCoolingGasScene), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " --set system.dimension=2 ";
  const std::string plain = scene + " -o " + out + " ";
  test::expect_simulate_refused(plain + "--set system.dimension=4", "system.dimension = 4 is out of range", out);
  test::expect_simulate_refused(plain + "--set system.dimension=0", "system.dimension = 0 is out of range", out);
  test::expect_simulate_refused(plain + "--set system.dimension=2.5", "system.dimension must be an integer", out);
  test::expect_simulate_refused(base + "--set system.init=fcc", "3D lattice", out);
  test::expect_simulate_refused(base + "--set system.phi=0.5", "reaches phi <= 0.45", out);
}

}  // namespace
}  // namespace coolgas
