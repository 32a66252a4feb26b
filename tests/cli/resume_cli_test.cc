// Exact resume from any stop, driven as a user would: a run stopped by
// SIGINT, SIGTERM, SIGHUP or SIGKILL at several moments and resumed to the
// end holds every dump and observable bit for bit as the uninterrupted run
// (the moments are named points, common/fault_point.h, so every machine
// stops the run at the same event); the dump grid does not change the
// trajectory; set-up stops at once on a signal; a damaged checkpoint,
// damaged /parameters and absurd particle counts are refused with one line
// (exit code 2) before anything is allocated.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "common/hdf5_file.h"
#include "common/trajectory/writer_lock.h"
#include "tests/support/cli_checks.h"
#include "tests/support/fault_points.h"
#include "tests/support/run_command.h"
#include "tests/support/same_trajectory.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

std::string write_scene(const std::string& dir) { return test::write_file(dir, "gas.toml", test::kCoolingGasScene); }

using test::expect_same_trajectory;

// Runs the scene to `out` with the fault `spec` armed (test::fault), after
// `env` (variables, or a command such as nohup), and returns the exit code.
int run_with_fault(const std::string& scene, const std::string& out, const std::string& spec,
                   const std::string& env = "") {
  return test::run_command(test::fault(spec) + env + " " + test::simulate(scene + " -o " + out)).exit_code;
}

class ResumeCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("resume_reference"));
    const auto r = test::run_command(test::simulate(write_scene(*dir_) + " -o " + *dir_ + "/whole.h5"));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    collisions_ = test::collisions_of(whole());
  }
  static void TearDownTestSuite() { delete dir_; }
  static std::string whole() { return *dir_ + "/whole.h5"; }
  // The uninterrupted run's collisions: stops are placed at fractions of
  // them, early, midway and late in the run.
  static inline std::int64_t collisions_ = 0;
  static std::string scene() { return *dir_ + "/gas.toml"; }

  // Stops a run with `signal` (KILL, or a signal its handler takes) at each
  // fraction of its events, resumes it to the end, and compares it with the
  // uninterrupted run.
  static void stop_resume_compare(const std::string& name, const std::string& signal, int expected_exit,
                                  const std::string& env) {
    const std::string dir = test::scratch_dir(name);
    for (const double fraction : {0.05, 0.3, 0.6}) {
      const std::string spec = test::events_at(fraction, collisions_, signal);
      const std::string out = dir + "/run" + std::to_string(int(fraction * 100)) + ".h5";
      ASSERT_EQ(run_with_fault(scene(), out, spec, env), expected_exit) << spec;
      const auto v = test::run_command(test::bin("coolgas-validate") + " " + out);
      EXPECT_EQ(v.exit_code, 0) << spec << ": " << v.out << v.err;
      const auto r = test::run_command(test::simulate("--resume " + out));
      ASSERT_EQ(r.exit_code, 0) << spec << ": " << r.err;
      expect_same_trajectory(whole(), out);
    }
  }

  static std::string* dir_;
};
std::string* ResumeCli::dir_ = nullptr;

// The signals are raised by the run itself at the named point, so their
// handler (common/interrupt.h) runs as for a signal from outside, at the
// same event on every machine.
TEST_F(ResumeCli, AfterSigintEveryLaterDumpIsBitIdentical) { stop_resume_compare("resume_sigint", "INT", 3, ""); }

TEST_F(ResumeCli, AfterSigtermEveryLaterDumpIsBitIdentical) { stop_resume_compare("resume_sigterm", "TERM", 3, ""); }

// A dropped ssh session or terminal (SIGHUP) stops a run as SIGINT does.
TEST_F(ResumeCli, AfterSighupEveryLaterDumpIsBitIdentical) { stop_resume_compare("resume_sighup", "HUP", 3, ""); }

// A run started under nohup keeps ignoring SIGHUP, as its user asked.
TEST_F(ResumeCli, UnderNohupSighupIsIgnored) {
  const std::string out = test::scratch_dir("resume_nohup") + "/run.h5";
  EXPECT_EQ(run_with_fault(scene(), out, test::events_at(0.2, collisions_, "HUP"), "nohup"), 0);
  expect_same_trajectory(whole(), out);
}

// With a checkpoint after every slice of events (COOLGAS_CHECKPOINT_INTERVAL=0),
// a SIGKILL resumes from a mid-run checkpoint (and replays the dumps written
// after it without writing them twice).
TEST_F(ResumeCli, AfterSigkillEveryLaterDumpIsBitIdentical) {
  stop_resume_compare("resume_sigkill", "", test::kKilled, "COOLGAS_CHECKPOINT_INTERVAL=0");
}

TEST_F(ResumeCli, ExtendingAFinishedRunContinuesExactly) {
  const std::string dir = test::scratch_dir("resume_extend");
  const std::string out = dir + "/part.h5";
  ASSERT_EQ(test::run_command(test::simulate(scene() + " -o " + out + " --set run.t_end=100")).exit_code, 0);
  const auto r = test::run_command(test::simulate("--resume " + out + " --set run.t_end=2000"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_same_trajectory(whole(), out);
}

// Observation never perturbs the trajectory: another dump grid gives the
// same positions and velocities at the dumps both grids have.
TEST_F(ResumeCli, TheDumpGridDoesNotChangeTheTrajectory) {
  const std::string dir = test::scratch_dir("resume_dump_grid");
  const std::string out = dir + "/sparse.h5";
  ASSERT_EQ(test::run_command(test::simulate(scene() + " -o " + out + " --set output.dumps_per_decade=3")).exit_code, 0);
  h5::Handle fa = h5::open_file(whole(), h5::Mode::kReadOnly), fb = h5::open_file(out, h5::Mode::kReadOnly);
  h5::Handle ta = h5::open_dataset(fa.id(), "particles/all/position/time");
  h5::Handle tb = h5::open_dataset(fb.id(), "particles/all/position/time");
  const auto times_a = h5::read_all<double>(ta.id()), times_b = h5::read_all<double>(tb.id());
  int common = 0;
  for (std::size_t j = 0; j < times_b.size(); ++j)
    for (std::size_t i = 0; i < times_a.size(); ++i) {
      if (times_a[i] != times_b[j]) continue;
      ++common;
      for (const char* el : {"particles/all/position/value", "particles/all/velocity/value"}) {
        h5::Handle da = h5::open_dataset(fa.id(), el), db = h5::open_dataset(fb.id(), el);
        const auto x = h5::read_row<double>(da.id(), i), y = h5::read_row<double>(db.id(), j);
        ASSERT_EQ(x.size(), y.size());
        EXPECT_EQ(std::memcmp(x.data(), y.data(), x.size() * sizeof(double)), 0) << el << " at t = " << times_a[i];
      }
    }
  EXPECT_GE(common, 4);  // t = 0, 1, 10, 100, 1000, 2000
}

// A long equilibration (hours: 1e6 collision times) stops at a signal that
// comes after its second slice of events (the named point `equilibration`,
// common/fault_point.h), with one line and nothing written. A signal the
// engine ignored would run the equilibration to its end: the test's time
// limit, not a measured time, fails that.
TEST(ResumeCliSetUp, SignalsStopALongEquilibrationAtOnce) {
  const std::string dir = test::scratch_dir("resume_setup_signal");
  const std::string scene = write_scene(dir);
  for (const char* signal : {"INT", "TERM", "HUP"}) {
    const std::string out = dir + "/melt.h5";
    const auto r = test::run_command(test::fault(std::string("equilibration:2:") + signal) +
                                     test::simulate(scene + " -o " + out + " --set system.equilibrate=1e6"));
    EXPECT_EQ(r.exit_code, 3) << signal << ": " << r.err;
    EXPECT_EQ(test::line_count(r.err), 1) << signal << ": " << r.err;
    EXPECT_NE(r.err.find(std::string("interrupted by SIG") + signal + " during set-up; nothing written"),
              std::string::npos)
        << r.err;
    EXPECT_FALSE(std::filesystem::exists(out)) << signal;
    EXPECT_FALSE(std::filesystem::exists(out + ".checkpoint")) << signal;
  }
}

// A checkpoint that does not read back whole is refused with one line; the
// trajectory itself is untouched.
TEST(ResumeCliDamage, ADamagedCheckpointIsRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("resume_damaged");
  const std::string out = dir + "/run.h5";
  ASSERT_EQ(test::run_command(test::simulate(write_scene(dir) + " -o " + out + " --set run.t_end=10")).exit_code, 0);
  const auto size = std::filesystem::file_size(out + ".checkpoint");
  std::filesystem::resize_file(out + ".checkpoint", size / 2);
  test::expect_refused_with_one_line(test::run_command(test::simulate("--resume " + out + " --set run.t_end=20")),
                                     "ends early");
  EXPECT_EQ(test::run_command(test::bin("coolgas-validate") + " " + out).exit_code, 0);
}

// A checkpoint path that is not a regular file is refused at once naming it:
// a link to /dev/zero was read for 2 GB before "out of memory", a directory
// failed as an internal error. A section claiming more elements than the
// file holds is damaged input, refused before anything is allocated for it.
TEST(ResumeCliDamage, ACheckpointThatIsNotARegularFileOrClaimsTooMuchIsRefused) {
  const std::string dir = test::scratch_dir("resume_checkpoint_kind");
  const std::string out = dir + "/run.h5", checkpoint = out + ".checkpoint";
  ASSERT_EQ(test::run_command(test::simulate(write_scene(dir) + " -o " + out + " --set run.t_end=10")).exit_code, 0);
  const std::string saved = dir + "/saved.checkpoint";
  std::filesystem::rename(checkpoint, saved);
  std::filesystem::create_symlink("/dev/zero", checkpoint);
  // (Read, it would never end: the test's time limit is the bound, not a measured time.)
  test::expect_refused_with_one_line(test::run_command(test::simulate("--resume " + out + " --set run.t_end=20")),
                                     "run.h5.checkpoint': it is not a regular file");
  std::filesystem::remove(checkpoint);
  std::filesystem::create_directory(checkpoint);
  test::expect_refused_with_one_line(test::run_command(test::simulate("--resume " + out + " --set run.t_end=20")),
                                     "it is not a regular file");
  std::filesystem::remove(checkpoint);
  // The first section's element count (after the 24-byte header, its name's
  // length and name and its element size) set to 2^60.
  std::filesystem::copy_file(saved, checkpoint);
  {
    std::fstream f(checkpoint, std::ios::in | std::ios::out | std::ios::binary);
    std::uint32_t name_length = 0;
    f.seekg(24);
    f.read(reinterpret_cast<char*>(&name_length), sizeof name_length);
    const std::uint64_t count = std::uint64_t(1) << 60;
    f.seekp(std::streamoff(24 + 4 + name_length + 8));
    f.write(reinterpret_cast<const char*>(&count), sizeof count);
  }
  test::expect_refused_with_one_line(test::run_command(test::simulate("--resume " + out + " --set run.t_end=20")),
                                     "run.h5.checkpoint': section 'run/physics' ends early");
  EXPECT_EQ(test::run_command(test::bin("coolgas-validate") + " " + out).exit_code, 0);
}

// A finished short run to damage; its checkpoint is removed, so --resume reads the trajectory itself.
std::string short_run(const std::string& dir) {
  std::string out = dir + "/run.h5";
  EXPECT_EQ(test::run_command(test::simulate(write_scene(dir) + " -o " + out + " --set run.t_end=10")).exit_code, 0);
  std::filesystem::remove(out + ".checkpoint");
  return out;
}

// Overwrites the 4 bytes at the first `signature` of an HDF5 structure in the file.
void overwrite_signature(const std::string& path, const std::string& signature) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const auto at = bytes.find(signature);
  ASSERT_NE(at, std::string::npos) << signature;
  f.seekp(std::streamoff(at));
  f.write("\xff\xff\xff\xff", 4);
}

std::string resume_to_20(const std::string& path) {
  return test::simulate("--resume " + path + " --set run.t_end=20");
}

// The whole file's bytes.
std::string file_bytes(const std::string& path) {
  std::ifstream f(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

// A file the validator rejects (here a dump time going back, written past the
// writer's checks) is refused with one line naming the problem, before a
// byte of it changes: appending would hide the damage.
TEST(ResumeCliDamage, AFileTheValidatorRejectsIsRefusedUnchanged) {
  const std::string dir = test::scratch_dir("resume_invalid");
  const std::string out = short_run(dir);
  {
    h5::Handle f = h5::open_file(out, h5::Mode::kReadWrite);
    h5::Handle t = h5::open_dataset(f.id(), "particles/all/position/time");
    std::vector<double> times = h5::read_all<double>(t.id());
    ASSERT_GE(times.size(), 3u);
    times[2] = -1;
    ASSERT_GE(H5Dwrite(t.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, times.data()), 0);
  }
  const std::string before = file_bytes(out);
  test::expect_refused_with_one_line(test::run_command(resume_to_20(out)), "[2] = -1 is less than an earlier");
  EXPECT_TRUE(file_bytes(out) == before) << "the refused file was changed";
}

// --force never replaces a file that another coolgas-simulate is writing
// (here: whose writer lock a live process holds): that writer would go on into
// an unlinked file and its checkpoints overwrite the new run's.
TEST(ResumeCliDamage, ForceRefusesAFileALiveWriterHolds) {
  const std::string dir = test::scratch_dir("resume_force_live");
  const std::string out = short_run(dir);
  const std::string before = file_bytes(out);
  const WriterLock held = WriterLock::take(out);
  test::expect_refused_with_one_line(test::run_command(test::simulate(write_scene(dir) + " -o " + out + " --force")),
                                     "is being written by another coolgas-simulate");
  EXPECT_TRUE(file_bytes(out) == before);
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

// A file written by an earlier version keeps a list of its free space, which
// HDF5 cannot open for SWMR writing and which goes stale when a writer is
// killed (the next writer then hands out space live objects hold). Its first
// resume converts it, through a copy, into the current format; a resume
// killed at any moment after that resumes exactly.
TEST_F(ResumeCli, AFileOfAnEarlierVersionIsConvertedAndResumesExactly) {
  const std::string dir = test::scratch_dir("resume_earlier_version");
  const std::string stopped = dir + "/stopped.h5", old = dir + "/old.h5";
  ASSERT_EQ(run_with_fault(scene(), stopped, test::events_at(0.2, collisions_, "INT")), 3);
  // h5repack rewrites it as the earlier versions created their files.
  ASSERT_EQ(test::run_command("h5repack -S PAGE -P 1 -G 4096 " + stopped + " " + old).exit_code, 0);
  std::filesystem::copy_file(stopped + ".checkpoint", old + ".checkpoint");
  const auto keeps_free_space = [](const std::string& path) {
    return test::run_command("h5dump -B -H " + path).out.find("FREE_SPACE_PERSIST TRUE") != std::string::npos;
  };
  ASSERT_TRUE(keeps_free_space(old));
  // Killed mid-run after the conversion (the resume has more events left
  // than 30 % of the whole run's collisions), then resumed to the end.
  const auto killed = test::run_command("COOLGAS_CHECKPOINT_INTERVAL=0 " +
                                        test::fault(test::events_at(0.3, collisions_)) +
                                        test::simulate("--resume " + old));
  ASSERT_EQ(killed.exit_code, test::kKilled) << killed.err;
  EXPECT_FALSE(keeps_free_space(old));
  const auto r = test::run_command(test::simulate("--resume " + old));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  expect_same_trajectory(whole(), old);
}

// The run parameters are attributes of /parameters: the strings live in the
// global heap (signature GCOL), the attribute table in a fractal heap (FHDB,
// the only one in the file). Either damaged, the reader names the first
// field it cannot read (the model, read first) instead of an HDF5 error.
TEST(ResumeCliDamage, DamagedParametersAreOneLineNamingTheField) {
  const std::string dir = test::scratch_dir("resume_damaged_parameters");
  const std::string run = short_run(dir);
  for (const char* signature : {"GCOL", "FHDB"}) {
    const std::string copy = dir + "/damaged_" + signature + ".h5";
    std::filesystem::copy_file(run, copy);
    overwrite_signature(copy, signature);
    test::expect_refused_with_one_line(test::run_command(resume_to_20(copy)),
                                       "/parameters attribute 'model' cannot be read: the file is damaged", signature);
  }
}

// Stored particle counts that would need terabytes: refused by the reader's
// checks (N against 32-bit ids, the memory, the datasets' shapes) before
// anything is allocated, instead of "out of memory" or the kernel's OOM killer.
TEST(ResumeCliDamage, AHugeStoredParticleCountIsRefusedBeforeAnyAllocation) {
  const std::string dir = test::scratch_dir("resume_huge_n");
  const std::string run = short_run(dir);
  const auto with_n = [&](std::int64_t n) {
    std::string copy = dir + "/N" + std::to_string(n) + ".h5";
    std::filesystem::copy_file(run, copy);
    h5::Handle f = h5::open_file(copy, h5::Mode::kReadWrite);
    h5::write_attr(h5::open_group(f.id(), "/parameters").id(), "N", n);
    return copy;
  };
  test::expect_refused_with_one_line(test::run_command(resume_to_20(with_n(1000000000000))),
                                     "/parameters/N = 1000000000000 is out of range");
  // In range for 32-bit ids, but 120 GB for the last dump alone (or, on a
  // machine that large, not the datasets' shape): refused either way.
  test::expect_refused_with_one_line(test::run_command(resume_to_20(with_n(2000000000))),
                                     "/parameters/N = 2000000000");
  // A position dataset declaring 10^12 particles per dump (chunked: it takes no space on disk).
  const std::string copy = dir + "/huge_dataset.h5";
  std::filesystem::copy_file(run, copy);
  {
    h5::Handle f = h5::open_file(copy, h5::Mode::kReadWrite);
    const std::string value = "/particles/all/position/value";
    const hsize_t frames = h5::shape(h5::open_dataset(f.id(), value).id())[0];
    ASSERT_GE(H5Ldelete(f.id(), value.c_str(), H5P_DEFAULT), 0);
    const hsize_t dims[3] = {frames, 1000000000000ULL, 3}, chunk[3] = {1, 4096, 3};
    h5::Handle space(H5Screate_simple(3, dims, nullptr)), dcpl(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(dcpl.id(), 3, chunk);
    h5::Handle ds(H5Dcreate2(f.id(), value.c_str(), H5T_IEEE_F64LE, space.id(), H5P_DEFAULT, dcpl.id(), H5P_DEFAULT));
    ASSERT_TRUE(ds.valid());
  }
  test::expect_refused_with_one_line(test::run_command(resume_to_20(copy)), "1000000000000, 3)");
}

}  // namespace
}  // namespace coolgas
