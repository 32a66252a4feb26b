// The effects models (viscoelastic, aggregation) driven as a user would: bad viscoelastic and
// aggregation parameters are refused with one line and exit code 2; an
// aggregation run validates (schema version 2), resumes bit for bit, and
// coolgas-clusters and coolgas-velocity read its aggregates; an elastic run
// still writes schema version 1.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "common/hdf5_file.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;
using test::simulate;
using test::write_file;

const char* kAggregationScene = R"([system]
N = 3000
phi = 0.208
seed = 5
[collision]
model = "aggregation"
[run]
t_end = 30
)";

void expect_refused(const std::string& args, const std::string& needle, const std::string& out) {
  test::expect_simulate_refused(args, needle, out);
}

TEST(EffectsCli, BadParametersAreRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("effects_bad_input");
  const std::string scene = write_file(dir, "ba.toml", kAggregationScene), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " ";
  expect_refused(base + "--set collision.model=sticky", "\"aggregation\"", out);
  expect_refused(base + "--set collision.r0=0.5", "collision.r0", out);
  expect_refused(base + "--set collision.delta=1e-4", "collision.delta", out);
  expect_refused(base + "--set collision.viscoelastic_b=0.1", "collision.viscoelastic_b", out);
  const std::string visco = base + "--set collision.model=viscoelastic ";
  expect_refused(visco, "collision.viscoelastic_b", out);  // the constant is required
  expect_refused(visco + "--set collision.viscoelastic_b=0", "collision.viscoelastic_b", out);
  expect_refused(visco + "--set collision.viscoelastic_b=-0.1", "collision.viscoelastic_b", out);
  expect_refused(visco + "--set collision.viscoelastic_b=nan", "collision.viscoelastic_b", out);
  expect_refused(visco + "--set collision.viscoelastic_b=0.1 --set collision.r0=0.5", "collision.r0", out);
  expect_refused(visco + "--set collision.viscoelastic_b=0.1 --set collision.delta=-1", "collision.delta", out);
  expect_refused(visco + "--set collision.viscoelastic_b=0.1 --set collision.viscoelsatic_b=0.1",
                 "did you mean 'collision.viscoelastic_b'", out);
  expect_refused(base + "--set collision.model=inelastic --set collision.viscoelastic_b=0.1",
                 "collision.viscoelastic_b", out);
}

std::int64_t schema_version(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle par = h5::open_group(f.id(), "parameters");
  return h5::read_attr_int(par.id(), "schema_version");
}

// Version 3: a viscoelastic file holds viscoelastic_b and delta, and no r0.
TEST(EffectsCli, ViscoelasticRunValidatesAsVersion3AndElasticStaysVersion1) {
  const std::string dir = test::scratch_dir("effects_visco");
  const std::string scene = write_file(dir, "ba.toml", kAggregationScene);
  const std::string visco = dir + "/visco.h5", elastic = dir + "/elastic.h5";
  ASSERT_EQ(run_command(simulate(scene + " -o " + visco +
                                 " --set collision.model=viscoelastic --set collision.viscoelastic_b=0.2"))
                .exit_code,
            0);
  ASSERT_EQ(run_command(simulate(scene + " -o " + elastic + " --set collision.model=elastic --set run.t_end=1"))
                .exit_code,
            0);
  const auto v = run_command(bin("coolgas-validate") + " " + visco);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("profile v3"), std::string::npos) << v.out;
  EXPECT_EQ(schema_version(visco), 3);
  {
    h5::Handle vf = h5::open_file(visco, h5::Mode::kReadOnly);
    h5::Handle par = h5::open_group(vf.id(), "parameters");
    EXPECT_EQ(h5::read_attr_double(par.id(), "viscoelastic_b"), 0.2);
    EXPECT_FALSE(h5::has_attr(par.id(), "r0"));
  }
  EXPECT_EQ(schema_version(elastic), 1);
  h5::Handle f = h5::open_file(elastic, h5::Mode::kReadOnly);
  EXPECT_FALSE(h5::exists(f.id(), "particles/all/id"));
  EXPECT_FALSE(h5::exists(f.id(), "observables/aggregates"));
}

template <class T>
std::vector<T> read(const std::string& path, const std::string& dataset) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle d = h5::open_dataset(f.id(), dataset);
  return h5::read_all<T>(d.id());
}

TEST(EffectsCli, AggregationRunValidatesResumesAndIsReadByTheTools) {
  const std::string dir = test::scratch_dir("effects_aggregation");
  const std::string scene = write_file(dir, "ba.toml", kAggregationScene);
  const std::string whole = dir + "/whole.h5", parts = dir + "/parts.h5";
  ASSERT_EQ(run_command(simulate(scene + " -o " + whole)).exit_code, 0);
  const auto v = run_command(bin("coolgas-validate") + " " + whole);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;

  // Observables against the dumps: mass conserved, counts agree, ids stable.
  const auto ids = read<std::int32_t>(whole, "particles/all/id/value");
  const auto mass = read<double>(whole, "particles/all/mass/value");
  const auto count = read<std::int64_t>(whole, "observables/aggregates/value");
  const std::size_t n = 3000, frames = ids.size() / n;
  ASSERT_GT(frames, 3u);
  double total = 0;
  std::int64_t present = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t k = (frames - 1) * n + i;
    total += mass[k];
    present += ids[k] >= 0;
    EXPECT_TRUE(ids[k] == std::int32_t(i) || ids[k] == -1) << i;
  }
  EXPECT_EQ(total, 3000.0);
  EXPECT_EQ(present, count.back());
  EXPECT_LT(present, 1500);  // it did aggregate

  // Resume from t = 1 reproduces the uninterrupted run.
  ASSERT_EQ(run_command(simulate(scene + " -o " + parts + " --set run.t_end=1")).exit_code, 0);
  const auto r = run_command(simulate("--resume " + parts + " --set run.t_end=30"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* ds : {"particles/all/position/value", "particles/all/velocity/value",
                         "particles/all/diameter/value", "observables/kinetic_energy/value"}) {
    const auto a = read<double>(whole, ds), b = read<double>(parts, ds);
    ASSERT_EQ(a.size(), b.size()) << ds;
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << ds << " differs";
  }
  EXPECT_EQ(read<std::int32_t>(parts, "particles/all/id/value"), ids);

  // coolgas-clusters: the clusters are the aggregates.
  const auto c = run_command(bin("coolgas-clusters") + " --series " + whole + " | tail -n 1");
  ASSERT_EQ(c.exit_code, 0) << c.err;
  std::istringstream row(c.out);
  double t = 0, m0 = 0;
  row >> t >> m0;
  EXPECT_EQ(t, 30.0);
  const double L = std::cbrt(3000 * M_PI / (6 * 0.208));
  EXPECT_NEAR(m0 * L * L * L, double(count.back()), 1e-6);  // M0 is clusters per volume
  const auto vel = run_command(bin("coolgas-velocity") + " " + whole + " --time 1");
  EXPECT_EQ(vel.exit_code, 0) << vel.err;
}

// Aggregates half the box wide could touch through two periodic images: the
// run stops with exit code 4, one line naming the fix, and a valid last dump.
TEST(EffectsCli, AggregatesOutgrowingASmallBoxStopTheRunCleanly) {
  const std::string dir = test::scratch_dir("effects_too_large");
  const std::string scene = write_file(dir, "ba.toml", kAggregationScene), out = dir + "/tiny.h5";
  const auto r = run_command(simulate(scene + " -o " + out + " --set system.N=300 --set run.t_end=1000"));
  EXPECT_EQ(r.exit_code, 4) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("larger system"), std::string::npos) << r.err;
  EXPECT_EQ(run_command(bin("coolgas-validate") + " " + out).exit_code, 0);
}

}  // namespace
}  // namespace coolgas
