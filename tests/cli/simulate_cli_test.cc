// coolgas-simulate driven as a user would: bad input is refused with one
// line and exit code 2 leaving no file; output validates and is read by
// MDAnalysis; --resume continues bit-identically; signals leave readable files.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/hdf5_file.h"
#include "tests/support/fault_points.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;
using test::simulate;

const char* kScene = R"([system]
N = 2000
phi = 0.208
seed = 3
[collision]
model = "inelastic"
r0 = 0.1
delta = 1e-4
[run]
t_end = 20
)";

std::string write_scene(const std::string& dir) { return test::write_file(dir, "gas.toml", kScene); }

void expect_refused(const std::string& args, const std::string& needle, const std::string& out) {
  test::expect_simulate_refused(args, needle, out);
}

TEST(SimulateCli, BadInputIsRefusedWithOneLineAndNoFile) {
  const std::string dir = test::scratch_dir("simulate_bad_input");
  const std::string scene = write_scene(dir), out = dir + "/out.h5";
  const std::string base = scene + " -o " + out + " ";
  expect_refused(base + "--set system.phy=0.1", "did you mean 'system.phi'", out);
  expect_refused(base + "--set system.phi=0", "system.phi", out);
  expect_refused(base + "--set system.phi=0.4", "random sequential addition", out);
  expect_refused(base + "--set system.N=1", "system.N", out);
  expect_refused(base + "--set collision.r0=0", "collision.r0", out);
  expect_refused(base + "--set collision.r0=1.01", "collision.r0", out);
  expect_refused(base + "--set collision.delta=-1e-4", "collision.delta", out);
  expect_refused(base + "--set run.t_end=0", "run.t_end", out);
  expect_refused(base + "--set run.t_end=-5", "run.t_end", out);
  expect_refused(base + "--bogus-flag", "bogus", out);
  expect_refused(dir + "/missing.toml -o " + out, "missing.toml", out);
  expect_refused(scene + " -o " + dir + "/no/such/dir/out.h5", "no directory", dir + "/no/such/dir/out.h5");
  expect_refused("--resume " + dir + "/missing.h5", "missing.h5", dir + "/missing.h5");
  std::ofstream(dir + "/corrupt.h5") << "not an HDF5 file\n";
  const auto r = run_command(simulate("--resume " + dir + "/corrupt.h5"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
}

// The longest output name allowed is the longest that works: the run also
// writes NAME.partial, NAME.checkpoint and NAME.checkpoint.partial, so names
// that passed a limit leaving room for ".partial" only failed later as an
// internal error (File name too long).
TEST(SimulateCli, TheStatedNameLimitIsTheEnforcedOne) {
  const std::string dir = test::scratch_dir("simulate_long_name");
  const std::string scene = write_scene(dir);
  long max = pathconf(dir.c_str(), _PC_NAME_MAX);
  if (max <= 0) max = 255;
  const std::size_t limit = std::size_t(max) - std::strlen(".checkpoint.partial");
  for (std::size_t length : {limit + 1, limit + 5, std::size_t(max) - std::strlen(".partial")}) {
    const std::string out = dir + "/" + std::string(length - 3, 'n') + ".h5";
    expect_refused(scene + " -o " + out + " --set run.t_end=1",
                   "the file name has " + std::to_string(length) + " characters; the limit here is " +
                       std::to_string(limit),
                   out);
  }
  const std::string out = dir + "/" + std::string(limit - 3, 'n') + ".h5";
  const auto r = run_command(simulate(scene + " -o " + out + " --set run.t_end=1"));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(std::filesystem::exists(out));
  EXPECT_TRUE(std::filesystem::exists(out + ".checkpoint"));
}

TEST(SimulateCli, ExistingOutputIsKeptWithoutForce) {
  const std::string dir = test::scratch_dir("simulate_existing");
  const std::string scene = write_scene(dir), out = dir + "/out.h5";
  std::ofstream(out) << "precious";
  const auto r = run_command(simulate(scene + " -o " + out));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--force"), std::string::npos);
  std::ifstream f(out);
  std::string content;
  f >> content;
  EXPECT_EQ(content, "precious");
  EXPECT_EQ(run_command(simulate(scene + " -o " + out + " --force")).exit_code, 0);
}

TEST(SimulateCli, OutputValidatesAndMDAnalysisReadsIt) {
  const std::string dir = test::scratch_dir("simulate_valid");
  const std::string out = dir + "/gas.h5";
  ASSERT_EQ(run_command(simulate(write_scene(dir) + " -o " + out)).exit_code, 0);
  const auto v = run_command(bin("coolgas-validate") + " " + out);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  h5::Handle f = h5::open_file(out, h5::Mode::kReadOnly);
  h5::Handle par = h5::open_group(f.id(), "parameters");
  const double L = h5::read_attr_double(par.id(), "L");
  const auto m = run_command("/usr/bin/python3 " + test::source("tests/cli/read_with_mdanalysis.py") + " " + out +
                             " 2000 " + std::to_string(L) + " 4");
  EXPECT_EQ(m.exit_code, 0) << m.out << m.err;
}

TEST(SimulateCli, SameSceneAndSeedGiveTheSameFrames) {
  const std::string dir = test::scratch_dir("simulate_repeat");
  const std::string scene = write_scene(dir);
  ASSERT_EQ(run_command(simulate(scene + " -o " + dir + "/a.h5")).exit_code, 0);
  ASSERT_EQ(run_command(simulate(scene + " -o " + dir + "/b.h5")).exit_code, 0);
  for (const char* ds : {"particles/all/position/value", "particles/all/velocity/value", "observables/kinetic_energy/value"}) {
    const auto d = run_command("h5diff " + dir + "/a.h5 " + dir + "/b.h5 /" + ds + " /" + ds);
    EXPECT_EQ(d.exit_code, 0) << ds << d.out;
  }
}

// Frames of `b` from index first_b on equal frames of `a` from first_a, bit for bit.
void expect_same_frames(const std::string& a, const std::string& b) {
  h5::Handle fa = h5::open_file(a, h5::Mode::kReadOnly), fb = h5::open_file(b, h5::Mode::kReadOnly);
  for (const char* el : {"particles/all/position", "particles/all/velocity", "observables/kinetic_energy",
                         "observables/collisions"}) {
    h5::Handle ta = h5::open_dataset(fa.id(), std::string(el) + "/time");
    h5::Handle tb = h5::open_dataset(fb.id(), std::string(el) + "/time");
    EXPECT_EQ(h5::read_all<double>(ta.id()), h5::read_all<double>(tb.id())) << el;
    h5::Handle va = h5::open_dataset(fa.id(), std::string(el) + "/value");
    h5::Handle vb = h5::open_dataset(fb.id(), std::string(el) + "/value");
    if (std::string(el) == "observables/collisions") {
      EXPECT_EQ(h5::read_all<std::int64_t>(va.id()), h5::read_all<std::int64_t>(vb.id())) << el;
    } else {
      const auto x = h5::read_all<double>(va.id()), y = h5::read_all<double>(vb.id());
      ASSERT_EQ(x.size(), y.size()) << el;
      EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << el << " differs";
    }
  }
}

TEST(SimulateCli, ResumeContinuesBitIdentically) {
  const std::string dir = test::scratch_dir("simulate_resume");
  const std::string scene = write_scene(dir);
  ASSERT_EQ(run_command(simulate(scene + " -o " + dir + "/whole.h5")).exit_code, 0);
  // Stop at t = 1 (a dump time of the log grid, exact in binary), then resume to 20.
  ASSERT_EQ(run_command(simulate(scene + " -o " + dir + "/parts.h5 --set run.t_end=1")).exit_code, 0);
  const auto r = run_command(simulate("--resume " + dir + "/parts.h5 --set run.t_end=20"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_same_frames(dir + "/whole.h5", dir + "/parts.h5");
  const auto again = run_command(simulate("--resume " + dir + "/parts.h5"));
  EXPECT_EQ(again.exit_code, 0);
  EXPECT_NE(again.err.find("nothing to do"), std::string::npos);
  const auto bad = run_command(simulate("--resume " + dir + "/parts.h5 --set system.N=10"));
  EXPECT_EQ(bad.exit_code, 2);
}

const char* kLongRun = " --set system.N=30000 --set run.t_end=1e6";

// Starts a long run, which waits after 10 events per particle (past its
// first dumps) until `signal` comes from outside; returns the exit code.
int run_and_signal(const std::string& dir, const std::string& signal) {
  const std::string out = dir + "/long.h5", ready = dir + "/ready";
  return run_command(test::when_ready(test::waiting_at("events:300000", ready) +
                                          simulate(write_scene(dir) + " -o " + out + kLongRun),
                                      ready, "kill -" + signal + " $pid"))
      .exit_code;
}

// The time of the last complete dump of a file.
double last_dump_time(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);  // closed again before resuming: HDF5 locks open files
  h5::Handle t = h5::open_dataset(f.id(), "restart/time");
  return h5::read_all<double>(t.id()).back();
}

// SIGINT stops the run with exit 3 (simulate/run/checkpoint.h: the exact
// state goes to the checkpoint beside the file; no off-grid dump is added),
// the file validates, and --resume carries it past its last dump.
TEST(SimulateCli, SigintLeavesAValidFileThatResumes) {
  const std::string dir = test::scratch_dir("simulate_sigint");
  EXPECT_EQ(run_and_signal(dir, "INT"), 3);
  EXPECT_EQ(run_command(bin("coolgas-validate") + " " + dir + "/long.h5").exit_code, 0);
  const double last = last_dump_time(dir + "/long.h5");
  EXPECT_GT(last, 0.0);
  const auto r = run_command(simulate("--resume " + dir + "/long.h5 --set run.t_end=" + std::to_string(last * 1.5)));
  EXPECT_EQ(r.exit_code, 0) << r.err;
}

// A run killed mid-run (after 10 events per particle) resumes from its last
// dump to past it, and every frame and observable equals the uninterrupted run's.
TEST(SimulateCli, AfterSigkillTheEarlierDumpsStillRead) {
  const std::string dir = test::scratch_dir("simulate_sigkill");
  EXPECT_EQ(run_command(test::fault("events:300000") + simulate(write_scene(dir) + " -o " + dir + "/long.h5" + kLongRun))
                .exit_code,
            test::kKilled);
  const auto v = run_command(bin("coolgas-validate") + " " + dir + "/long.h5");
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  const double last = last_dump_time(dir + "/long.h5");
  const std::string t_end = test::format_exact(std::max(2 * last, 0.1));  // past the last dump: the resume runs
  const auto r = run_command(simulate("--resume " + dir + "/long.h5 --set run.t_end=" + t_end));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_GT(last_dump_time(dir + "/long.h5"), last);
  const auto whole = run_command(simulate(write_scene(dir) + " -o " + dir + "/whole.h5" + kLongRun +
                                          " --set run.t_end=" + t_end));
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  expect_same_frames(dir + "/whole.h5", dir + "/long.h5");
}

}  // namespace
}  // namespace coolgas
