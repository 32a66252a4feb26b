// coolgas-simulate with system.dimension = 1 (hard rods on a ring), driven
// as a user would: the file is H5MD with box/dimension = 1 and 1-component
// vectors, the validator accepts it, a run extended or stopped and resumed
// is bit for bit the uninterrupted one, and what 1D refuses is one line each.
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

// The resume tests' cooling gas as rods, to t = 30 (in 1D its clusters
// collide far more often below delta than disks do: a longer run is slow).
std::string rods(const std::string& args, const char* t_end = "30") {
  return test::simulate(args + " --set system.dimension=1 --set run.t_end=" + t_end);
}

class RodsCli : public test::OneRunSuite<RodsCli> {
 public:
  static constexpr const char* kFolder = "rods_cli";
  static constexpr const char* kScene = test::kCoolingGasScene;
  static std::string launch(const std::string& args) { return rods(args); }
};

TEST_F(RodsCli, TheFileIsA1DH5mdFileTheValidatorAccepts) {
  const auto v = run_command(bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  h5::Handle box = h5::open_group(f.id(), "particles/all/box");
  EXPECT_EQ(h5::read_attr_int(box.id(), "dimension"), 1);
  EXPECT_EQ(h5::read_attr_strings(box.id(), "boundary"), (std::vector<std::string>{"periodic"}));
  for (const char* element : {"position", "velocity", "image"}) {
    h5::Handle d = h5::open_dataset(f.id(), std::string("particles/all/") + element + "/value");
    EXPECT_EQ(h5::shape(d.id()).at(1), 8000u) << element;
    EXPECT_EQ(h5::shape(d.id()).at(2), 1u) << element;
  }
  h5::Handle edges = h5::open_dataset(f.id(), "particles/all/box/edges/value");
  EXPECT_EQ(h5::shape(edges.id()).at(1), 1u);
  EXPECT_EQ(h5::shape(edges.id()).at(2), 1u);
  h5::Handle p = h5::open_dataset(f.id(), "observables/total_momentum/value");
  EXPECT_EQ(h5::shape(p.id()).at(1), 1u);
}

TEST_F(RodsCli, AnExtendedRunIsBitForBitTheWholeOne) {
  const std::string out = dir_ + "/part.h5";
  ASSERT_EQ(run_command(rods(scene_ + " -o " + out, "10")).exit_code, 0);  // t = 10 is on the dump grid
  const auto r = run_command(test::simulate("--resume " + out + " --set run.t_end=30"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  test::expect_same_trajectory(whole(), out);
}

// Killed mid-run (halfway through the whole run's collisions, a checkpoint
// after every slice of events), resumed from its checkpoint.
TEST_F(RodsCli, AKilledRunResumesBitForBit) {
  const std::string out = dir_ + "/killed.h5";
  test::expect_killed_run_resumes_bit_for_bit(rods(scene_ + " -o " + out), out, whole());
}

TEST_F(RodsCli, EstimateAndProgressWorkIn1D) {
  const auto e = run_command(rods(scene_ + " -o " + dir_ + "/estimate.h5 --estimate"));
  EXPECT_EQ(e.exit_code, 0) << e.err;
  EXPECT_FALSE(e.out.empty());
  EXPECT_FALSE(std::filesystem::exists(dir_ + "/estimate.h5"));
}

// Ballistic aggregation of rods: the file (1-component vectors, masses and
// lengths), the validator, and a run extended from t = 10 bit for bit the
// whole one, aggregates included.
constexpr const char* kRodAggregationScene = R"([system]
dimension = 1
N = 8000
phi = 0.2
seed = 4
equilibrate = 0
[collision]
model = "aggregation"
[run]
t_end = 300
[output]
dumps_per_decade = 10
)";

TEST(RodsCliAggregation, AnExtendedRunIsBitForBitTheWholeOneAndValid) {
  const std::string dir = test::scratch_dir("rods_aggregation");
  const std::string scene = test::write_file(dir, "agg.toml", kRodAggregationScene);
  const std::string whole = dir + "/whole.h5", part = dir + "/part.h5";
  const auto r = run_command(test::simulate(scene + " -o " + whole));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto v = run_command(bin("coolgas-validate") + " " + whole);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  ASSERT_EQ(run_command(test::simulate(scene + " -o " + part + " --set run.t_end=10")).exit_code, 0);
  const auto resumed = run_command(test::simulate("--resume " + part + " --set run.t_end=300"));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  test::expect_same_trajectory(whole, part);
  h5::Handle fa = h5::open_file(whole, h5::Mode::kReadOnly), fb = h5::open_file(part, h5::Mode::kReadOnly);
  for (const char* ds : {"particles/all/mass/value", "particles/all/diameter/value", "particles/all/id/value"})
    EXPECT_TRUE(test::dataset_bytes(fa.id(), ds) == test::dataset_bytes(fb.id(), ds)) << ds;
  h5::Handle d = h5::open_dataset(fa.id(), "particles/all/position/value");
  EXPECT_EQ(h5::shape(d.id()).at(2), 1u);
}

TEST(RodsCliScene, WhatRodsRefuseIsOneLineEach) {
  const std::string dir = test::scratch_dir("rods_bad_scene");
  const std::string scene = test::write_file(dir, "gas.toml", test::kCoolingGasScene), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " --set system.dimension=1 ";
  test::expect_simulate_refused(base + "--set system.init=fcc", "3D lattice", out);
  test::expect_simulate_refused(base + "--set system.phi=1", "system.phi = 1 is out of range", out);
  test::expect_simulate_refused(base + "--set system.phi=1.5", "system.phi = 1.5 is out of range", out);
  // N and L give phi = N / L: at N = L the rods would cover the ring.
  test::expect_simulate_refused(base + "--set system.L=8000 --set system.N=8000", "need N < L", out);
}

}  // namespace
}  // namespace coolgas
