// The trajectory file survives what real runs meet (common/trajectory/
// h5md_writer.h): SIGKILL at any moment (named points over the whole run,
// common/fault_point.h) leaves every earlier dump valid and the file resumable; the analysis tools read a file that is still being
// written; a write that fails (here: a file-size limit, as a full disk
// would) is one line naming the file and the cause, exit code 5, the earlier
// dumps intact, and --resume completes the run once the limit is lifted.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "tests/support/fault_points.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;

// 5968 particles (a frame is 358 kB), dumps 10 per decade from t = 0.01 to
// 300: about 1.5 s, 17 MB.
constexpr const char* kScene =
    "[system]\nL = 25\nphi = 0.2\nseed = 3\nequilibrate = 0.5\n"
    "[collision]\nmodel = \"inelastic\"\nr0 = 0.9\ndelta = 1e-4\n"
    "[run]\nt_end = 300\n[output]\ndumps_per_decade = 10\n";

std::string write_scene(const std::string& dir) {
  std::string path = dir + "/scene.toml";
  run_command("printf '%s' '" + std::string(kScene) + "' > " + path);
  return path;
}

std::vector<double> dump_times(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle t = h5::open_dataset(f.id(), "restart/time");
  return h5::read_all<double>(t.id());
}

std::string validate(const std::string& path) {
  const auto v = run_command(bin("coolgas-validate") + " " + path);
  return v.exit_code == 0 ? "" : v.out + v.err;
}

class TrajectorySafety : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = test::scratch_dir("trajectory_safety");
    scene = write_scene(dir);
    const auto r = run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + dir + "/whole.h5");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    whole = dump_times(dir + "/whole.h5");
  }
  std::string dir, scene;
  std::vector<double> whole;  // the dump times of the uninterrupted run
};

// Kills spread over the run, from its first dumps to its last: after a
// number of events, amid a dump's rows (before they are flushed, and
// flushed before the row that marks the dump complete), amid a mid-run
// checkpoint and before its rename. Whatever was being written at that
// moment, the dumps before it are complete and valid, and --resume runs the
// rest to the uninterrupted run's dumps.
TEST_F(TrajectorySafety, SigkillAtAnyMomentLeavesEveryEarlierDumpValidAndResumable) {
  const std::int64_t collisions = test::collisions_of(dir + "/whole.h5");
  const auto dumps = long(whole.size());
  ASSERT_GE(dumps, 10);
  // (Every point, in every kind of run: fault_points_cli_test.cc.)
  const std::vector<std::string> points = {
      test::events_at(0.2, collisions), test::events_at(0.5, collisions), test::events_at(0.8, collisions),
      "dump-frame:2", "dump-flushed:" + std::to_string(dumps / 2), "dump-flushed:" + std::to_string(dumps),
      "checkpoint-write:3"};
  for (const std::string& point : points) {
    const std::string out = dir + "/killed_" + point.substr(0, point.find(':')) + "_" +
                            point.substr(point.find(':') + 1) + ".h5";
    // A checkpoint after every slice of events, so the checkpoint points land mid-run.
    const auto k = run_command("COOLGAS_CHECKPOINT_INTERVAL=0 " + test::fault(point) + bin("coolgas-simulate") + " " +
                               scene + " -q -o " + out);
    ASSERT_EQ(k.exit_code, test::kKilled) << point << ": the fault did not stop the run: " << k.err;
    EXPECT_EQ(validate(out), "") << "killed at " << point;
    const auto before = dump_times(out);
    ASSERT_LT(before.size(), whole.size()) << point;
    EXPECT_EQ(before, std::vector<double>(whole.begin(), whole.begin() + long(before.size()))) << point;
    const auto r = run_command(bin("coolgas-simulate") + " -q --resume " + out);
    EXPECT_EQ(r.exit_code, 0) << point << ": " << r.err;
    EXPECT_EQ(validate(out), "") << "resumed after a kill at " << point;
    EXPECT_EQ(dump_times(out), whole) << point;
  }
}

// A reader opens the file while coolgas-simulate writes it (HDF5 SWMR) and
// sees the complete dumps so far; a second writer is refused. The writer
// waits with its 4th dump's rows written but not flushed (the named point
// `dump-frame`, common/fault_point.h) while the readers read: three
// complete dumps, on every machine.
TEST_F(TrajectorySafety, ToolsReadAFileWhileItIsWrittenAndASecondWriterIsRefused) {
  const std::string out = dir + "/live.h5", ready = dir + "/ready";
  const auto r = run_command(test::when_ready(
      test::waiting_at("dump-frame:4", ready) + bin("coolgas-simulate") + " " + scene + " -q -o " + out, ready,
      bin("coolgas-validate") + " " + out + " && " + bin("coolgas-energy") + " " + out + " | tail -1 && " +
          bin("coolgas-clusters") + " --series " + out + " | tail -1; " + bin("coolgas-simulate") + " -q --resume " +
          out + "; echo resume=$?; kill -KILL $pid"));
  EXPECT_NE(r.out.find(" 5968 particles, 3 frames, "), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.out.find("resume=2"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("is being written by another coolgas-simulate"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("internal error"), std::string::npos) << r.err;
}

// A run killed after a dump leaves the killed writer's "open for writing"
// flags in its file; a --resume that has nothing left to do (its t_end is
// that dump) still clears them, so that programs that are not SWMR readers
// (h5dump, h5diff, MDAnalysis) open the file.
TEST_F(TrajectorySafety, AResumeWithNothingToDoClosesAKilledRunsFileProperly) {
  const std::string out = dir + "/killed.h5";
  ASSERT_EQ(run_command(test::fault("dump-frame:4") + bin("coolgas-simulate") + " " + scene + " -q -o " + out +
                        " --set run.t_end=1e8").exit_code,
            test::kKilled);  // killed writing its 4th dump: three complete
  const hid_t plain = H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_LT(plain, 0) << "the killed writer left no flags: nothing to test";
  const auto times = dump_times(out);
  const auto r = run_command(bin("coolgas-simulate") + " -q --resume " + out + " --set run.t_end=" +
                             test::format_exact(times.back()));
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("nothing to do"), std::string::npos) << r.err;
  h5::Handle reopened(H5Fopen(out.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  EXPECT_TRUE(reopened.valid());
  EXPECT_EQ(dump_times(out), times);
}

// ulimit -f stands for a full disk or quota: SIGXFSZ is ignored, so the write
// fails with EFBIG and the run stops with one line and exit code 5.
TEST_F(TrajectorySafety, AFailedWriteIsOneLineExit5AndResumeCompletesTheRun) {
  const std::string out = dir + "/limited.h5";
  const auto r = run_command("ulimit -f 8000; " + bin("coolgas-simulate") + " " + scene + " -q -o " + out);
  EXPECT_EQ(r.exit_code, kExitWrite) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("cannot write '" + out + "': File too large"), std::string::npos) << r.err;
  EXPECT_EQ(validate(out), "");
  const auto before = dump_times(out);
  ASSERT_GT(before.size(), 2u);
  ASSERT_LT(before.size(), whole.size());
  const auto resumed = run_command(bin("coolgas-simulate") + " -q --resume " + out);
  EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
  EXPECT_EQ(validate(out), "");
  EXPECT_EQ(dump_times(out), whole);
}

// A disk already full when the run starts: HDF5 cannot even create the file.
// The run says the system's reason (not "directory missing or not
// writable?"), exits with code 5 and leaves no file behind (the create left
// a 0-byte FILE.partial). A full disk needs a small file system of its own:
// a 200 kB tmpfs, which takes root; elsewhere the test is skipped.
TEST_F(TrajectorySafety, AFullDiskAtTheStartIsExit5LeavingNothing) {
  const std::string disk = dir + "/disk";
  run_command("mkdir -p " + disk);
  if (run_command("mount -t tmpfs -o size=200k tmpfs " + disk).exit_code != 0)
    GTEST_SKIP() << "cannot mount a small tmpfs here (not root)";
  run_command("dd if=/dev/zero of=" + disk + "/fill bs=1k count=400");
  const std::string out = disk + "/run.h5";
  const auto r = run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + out);
  const std::string left = run_command("ls " + disk).out;
  run_command("umount " + disk);
  EXPECT_EQ(r.exit_code, kExitWrite) << r.err;
  EXPECT_EQ(test::line_count(r.err), 1) << r.err;
  EXPECT_NE(r.err.find("run.h5.partial': No space left on device"), std::string::npos) << r.err;
  EXPECT_EQ(left, "fill\n");
}

// A disk with a few kilobytes free: the file is created, then setting up
// its objects fails. Exit 5 with one line and nothing left behind (HDF5's
// clean-up at exit once crashed on the file whose close had failed).
TEST_F(TrajectorySafety, ADiskWithAFewKilobytesFreeIsExit5LeavingNothing) {
  const std::string disk = dir + "/small";
  run_command("mkdir -p " + disk);
  for (const int kb : {8, 12, 16, 24, 32}) {
    if (run_command("mount -t tmpfs -o size=" + std::to_string(kb) + "k tmpfs " + disk).exit_code != 0)
      GTEST_SKIP() << "cannot mount a small tmpfs here (not root)";
    const auto r = run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + disk + "/run.h5");
    const std::string left = run_command("ls " + disk).out;
    run_command("umount " + disk);
    EXPECT_EQ(r.exit_code, kExitWrite) << kb << " kB: " << r.err;
    EXPECT_EQ(test::line_count(r.err), 1) << r.err;
    EXPECT_EQ(left, "") << kb << " kB";
  }
}

// The same run as `whole`, stopped at its first dumps, then extended.
std::string same_as(const std::string& a, const std::string& b) {
  const auto d = run_command("h5diff " + a + " " + b + " /particles && h5diff " + a + " " + b + " /observables");
  return d.exit_code == 0 ? "" : d.out + d.err;
}

// A file-size limit (as a full disk) met by an extension, in its first
// moments (the file grown for the interrupted burst's chunks, before
// HDF5 records that end) or later: exit 5 with one line, the file as valid
// as before, and a --resume without the limit carries it to the
// uninterrupted run's result bit for bit. (The end of allocation once reached
// the superblock before the file had grown: HDF5 then refused the file as
// truncated, for good.)
TEST_F(TrajectorySafety, AWriteFailingDuringAnExtensionLeavesTheRunResumable) {
  const std::string part = dir + "/part.h5";
  ASSERT_EQ(run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + part + " --set run.t_end=3").exit_code, 0);
  const auto kb = std::filesystem::file_size(part) / 1024;
  for (const auto extra : {8, 400, 3000}) {
    const std::string out = dir + "/extended_" + std::to_string(extra) + ".h5";
    std::filesystem::copy_file(part, out);
    std::filesystem::copy_file(part + ".checkpoint", out + ".checkpoint");
    const auto r = run_command("ulimit -f " + std::to_string(kb + extra) + "; " + bin("coolgas-simulate") +
                               " -q --resume " + out + " --set run.t_end=300");
    EXPECT_EQ(r.exit_code, kExitWrite) << "+" << extra << " kB: " << r.err;
    EXPECT_EQ(test::line_count(r.err), 1) << r.err;
    EXPECT_EQ(validate(out), "") << "+" << extra << " kB";
    const auto resumed = run_command(bin("coolgas-simulate") + " -q --resume " + out + " --set run.t_end=300");
    EXPECT_EQ(resumed.exit_code, 0) << resumed.err;
    EXPECT_EQ(same_as(dir + "/whole.h5", out), "") << "+" << extra << " kB";
  }
}

// A file whose superblock records more bytes than it holds (what the defect
// above left) is refused by HDF5 as truncated: the tools say what repairs it,
// and --resume repairs it itself (zeros up to the recorded end, past the last
// complete dump) and continues exactly.
TEST_F(TrajectorySafety, AFileRecordingMoreBytesThanItHoldsIsRepairedByResume) {
  const std::string out = dir + "/short.h5";
  ASSERT_EQ(run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + out + " --set run.t_end=3").exit_code, 0);
  const auto size = std::filesystem::file_size(out);
  ASSERT_EQ(run_command("h5clear --increment=65536 " + out).exit_code, 0);
  std::filesystem::resize_file(out, size);
  const auto v = run_command(bin("coolgas-validate") + " " + out);
  EXPECT_EQ(v.exit_code, 2) << v.err;
  EXPECT_NE(v.err.find("'h5clear -s "), std::string::npos) << v.err;
  EXPECT_NE(v.err.find("' or a --resume repairs that"), std::string::npos) << v.err;
  const auto r = run_command(bin("coolgas-simulate") + " -q --resume " + out + " --set run.t_end=300");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(same_as(dir + "/whole.h5", out), "");
}

// While one --resume runs, a second of the same file is refused. (The lock
// once went with the first close of any other descriptor of the file, which
// a resume makes by reading it: two writers then wrote one file.) The first
// waits after its first event (the named point `events`), having read,
// checked and reopened the file, while the second starts.
TEST_F(TrajectorySafety, ASecondResumeOfARunningResumeIsRefused) {
  const std::string out = dir + "/twice.h5", ready = dir + "/ready";
  ASSERT_EQ(run_command(bin("coolgas-simulate") + " " + scene + " -q -o " + out + " --set run.t_end=3").exit_code, 0);
  const std::string resume = bin("coolgas-simulate") + " -q --resume " + out + " --set run.t_end=1e8";
  const auto r = run_command(test::when_ready(test::waiting_at("events:1", ready) + resume, ready,
                                              resume + "; echo second=$?; kill -KILL $pid"));
  EXPECT_NE(r.out.find("second=2"), std::string::npos) << r.out << r.err;
  EXPECT_NE(r.err.find("is being written by another coolgas-simulate"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace coolgas
