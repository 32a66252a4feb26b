// The named fault points (common/fault_point.h): coolgas-simulate killed at
// each of them, in a fresh run, a resume, a resume of a run killed amid a
// dump, an extension and the conversion of an earlier version's file, leaves
// a file that coolgas-validate accepts (or, before the first dump is in
// place, none), and the same command again finishes it to the uninterrupted
// run's file bit for bit. A signal raised at a point runs its handler as a
// signal from outside would; a run held at a point (WAIT) stays there until a
// signal from outside comes, then handles it, and one that waits and is told
// to go on ends as if it had not; a malformed COOLGAS_FAULT is refused with
// one line; a fault the run never reaches changes nothing.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "tests/support/cli_checks.h"
#include "tests/support/fault_points.h"
#include "tests/support/run_command.h"
#include "tests/support/same_trajectory.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::run_command;

// The resume tests' cooling gas, smaller and shorter (a fraction of a second).
constexpr const char* kSmall = " --set system.N=2000 --set run.t_end=300";

// A fault and the exit code it ends the run with.
struct Case {
  std::string spec;
  int exit_code = test::kKilled;
};

bool exists(const std::string& path) { return std::filesystem::exists(path); }

// A run's files (trajectory and checkpoint) copied to `to`.
void copy_run(const std::string& from, const std::string& to) {
  std::filesystem::copy_file(from, to);
  if (exists(from + ".checkpoint")) std::filesystem::copy_file(from + ".checkpoint", to + ".checkpoint");
}

class FaultPoints : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::string(test::scratch_dir("fault_points_reference"));
    scene_ = new std::string(test::write_file(*dir_, "gas.toml", test::kCoolingGasScene));
    const auto r = run_command(test::simulate(*scene_ + " -o " + whole() + kSmall));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    collisions_ = test::collisions_of(whole());
    h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
    dumps_ = h5::read_all<double>(h5::open_dataset(f.id(), "restart/time").id()).size();
  }
  static void TearDownTestSuite() {
    delete dir_;
    delete scene_;
  }
  static std::string whole() { return *dir_ + "/whole.h5"; }
  static std::string fresh(const std::string& out) { return test::simulate(*scene_ + " -o " + out + kSmall); }

  // For each case: `command` (with OUT standing for the file) run on a copy
  // of `base` (none: a fresh run) with the fault armed and a checkpoint
  // after every slice of events (so the checkpoint points land mid-run too);
  // then the file validates, and `again` (a fresh run when the fault left
  // no file) carries it to the uninterrupted run's, leaving no temporary file.
  static void kill_then_finish(const std::string& name, const std::string& base, const std::string& command,
                               const std::string& again, const std::vector<Case>& cases) {
    const std::string dir = test::scratch_dir(name);
    int k = 0;
    for (const Case& c : cases) {
      const std::string out = dir + "/run" + std::to_string(k++) + ".h5";
      if (!base.empty()) copy_run(base, out);
      const auto with_out = [&](std::string s) {
        for (auto at = s.find("OUT"); at != std::string::npos; at = s.find("OUT")) s.replace(at, 3, out);
        return s;
      };
      const auto r = run_command("COOLGAS_CHECKPOINT_INTERVAL=0 " + test::fault(c.spec) + with_out(command));
      ASSERT_EQ(r.exit_code, c.exit_code) << c.spec << ": " << r.err;
      if (exists(out)) {
        const auto v = run_command(test::bin("coolgas-validate") + " " + out);
        EXPECT_EQ(v.exit_code, 0) << c.spec << ": " << v.out << v.err;
      }
      const auto a = run_command(exists(out) ? with_out(again) : fresh(out));
      ASSERT_EQ(a.exit_code, 0) << c.spec << ": " << a.err;
      test::expect_same_trajectory(whole(), out);
      EXPECT_FALSE(exists(out + ".partial")) << c.spec;
      EXPECT_FALSE(exists(out + ".checkpoint.partial")) << c.spec;
    }
  }

  static inline std::string* dir_ = nullptr;
  static inline std::string* scene_ = nullptr;
  static inline std::int64_t collisions_ = 0;  // the uninterrupted run's
  static inline std::size_t dumps_ = 0;        // its dumps
};

TEST_F(FaultPoints, AFreshRunKilledAtEachPointFinishesExactly) {
  const std::string last = std::to_string(dumps_);
  kill_then_finish("fault_points_fresh", "", fresh("OUT"), test::simulate("--resume OUT"),
                   {{test::events_at(0.1, collisions_)},
                    {test::events_at(0.7, collisions_)},
                    {"checkpoint-write"},  // the first, at t = 0: the trajectory not yet in place
                    {"checkpoint-rename"},
                    {"checkpoint-write:3"},
                    {"checkpoint-rename:3"},
                    {"dump-frame"},
                    {"dump-flushed"},
                    {"dump-frame:5"},
                    {"dump-flushed:5"},
                    {"dump-frame:" + last},
                    {"dump-flushed:" + last},
                    // raised signals: the handler checkpoints, exit 3
                    {test::events_at(0.4, collisions_, "INT"), 3},
                    {"dump-frame:6:TERM", 3},
                    {"checkpoint-write:4:HUP", 3}});
}

// A resume of a run stopped by SIGINT at 30 % of the whole run's
// collisions (counted as events), killed from its first moments on.
TEST_F(FaultPoints, AResumeKilledAtEachPointFinishesExactly) {
  const std::string stopped = test::scratch_dir("fault_points_resume_base") + "/stopped.h5";
  ASSERT_EQ(run_command(test::fault(test::events_at(0.3, collisions_, "INT")) + fresh(stopped)).exit_code, 3);
  const std::string resume = test::simulate("--resume OUT");
  kill_then_finish("fault_points_resume", stopped, resume, resume,
                   {{"resume-claimed"},
                    {"resume-reopened"},
                    {"dump-frame"},
                    {"dump-flushed"},
                    {"checkpoint-write"},
                    {"checkpoint-rename"},
                    {test::events_at(0.3, collisions_)},
                    {test::events_at(0.3, collisions_, "INT"), 3}});
}

// A resume of a run killed amid a dump's rows, which the resume drops first.
TEST_F(FaultPoints, AResumeOfARunKilledAmidADumpFinishesExactly) {
  const std::string torn = test::scratch_dir("fault_points_torn_base") + "/torn.h5";
  ASSERT_EQ(run_command(test::fault("dump-frame:" + std::to_string(dumps_ / 2)) + fresh(torn)).exit_code,
            test::kKilled);
  const std::string resume = test::simulate("--resume OUT");
  kill_then_finish("fault_points_torn", torn, resume, resume,
                   {{"resume-claimed"}, {"resume-reopened"}, {"dump-frame"}, {"dump-flushed"}});
}

// An extension (--set run.t_end) changes the stored scene in a copy that
// replaces the file whole.
TEST_F(FaultPoints, AnExtensionKilledAtEachPointFinishesExactly) {
  const std::string part = test::scratch_dir("fault_points_extend_base") + "/part.h5";
  ASSERT_EQ(run_command(test::simulate(*scene_ + " -o " + part + kSmall + " --set run.t_end=100")).exit_code, 0);
  const std::int64_t left = collisions_ - test::collisions_of(part);
  const std::string extend = test::simulate("--resume OUT --set run.t_end=300");
  kill_then_finish("fault_points_extend", part, extend, extend,
                   {{"replace-rename"},
                    {"resume-reopened"},
                    {"dump-frame"},
                    {"dump-flushed"},
                    {test::events_at(0.5, left)}});
}

// A file of an earlier version (h5repack writes it as they did: a list of
// free space kept) is converted once, object by object into a copy that
// replaces it whole; killed amid the conversion, the file is still the old
// one, and the next resume converts it.
TEST_F(FaultPoints, AConversionKilledAtEachPointFinishesExactly) {
  const std::string base_dir = test::scratch_dir("fault_points_convert_base");
  const std::string stopped = base_dir + "/stopped.h5", old = base_dir + "/old.h5";
  ASSERT_EQ(run_command(test::fault(test::events_at(0.3, collisions_, "INT")) + fresh(stopped)).exit_code, 3);
  ASSERT_EQ(run_command("h5repack -S PAGE -P 1 -G 4096 " + stopped + " " + old).exit_code, 0);
  std::filesystem::copy_file(stopped + ".checkpoint", old + ".checkpoint");
  const std::string resume = test::simulate("--resume OUT");
  kill_then_finish("fault_points_convert", old, resume, resume,
                   {{"convert"},
                    {"convert:3"},
                    {"replace-rename"},
                    {"resume-reopened"},
                    {test::events_at(0.3, collisions_)}});
}

// A run held at a point says so and waits there for a signal from outside:
// SIGTERM, sent once the line is seen, finds it at that point (its
// checkpoint is within the engine's 4096 events of checking the flag past
// it, far from the end), it exits 3, and --resume finishes it exactly.
TEST_F(FaultPoints, ARunHeldAtAPointWaitsForASignalThenFinishesExactly) {
  const std::string dir = test::scratch_dir("fault_points_held");
  const std::string out = dir + "/run.h5", err = dir + "/err.txt";
  const std::int64_t k = std::max<std::int64_t>(1, collisions_ / 5);
  const std::string held = "COOLGAS_CHECKPOINT_INTERVAL=0 " + test::fault("events:" + std::to_string(k) + ":WAIT") +
                           fresh(out) + " 2>" + err + " & pid=$!; "
                           "while kill -0 $pid 2>/dev/null && ! grep -qs 'fault: holding' " + err + "; do sleep 0.05; done; "
                           "kill -TERM $pid; wait $pid";
  const auto r = run_command(held);
  const std::string said = test::read_text(err);
  ASSERT_EQ(r.exit_code, 3) << said;
  EXPECT_NE(said.find("coolgas: fault: holding at COOLGAS_FAULT = 'events:" + std::to_string(k) +
                      ":WAIT' until SIGINT, SIGTERM, SIGHUP or SIGCONT"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("interrupted by SIGTERM"), std::string::npos) << said;
  EXPECT_LE(test::collisions_of(out), k + 4096);
  ASSERT_TRUE(exists(out + ".checkpoint"));
  const auto a = run_command(test::simulate("--resume " + out));
  ASSERT_EQ(a.exit_code, 0) << a.err;
  test::expect_same_trajectory(whole(), out);
}

// A run that waits at a point (WAIT) and is told to go on (SIGCONT) ends as
// the uninterrupted run, bit for bit; the file it waits in validates.
TEST_F(FaultPoints, ARunThatWaitedAtAPointAndWentOnFinishesExactly) {
  const std::string dir = test::scratch_dir("fault_points_wait");
  const std::string out = dir + "/run.h5", ready = dir + "/ready";
  const auto r = run_command(test::when_ready(test::waiting_at("dump-flushed:5", ready) + fresh(out), ready,
                                              test::bin("coolgas-validate") + " " + out + "; kill -CONT $pid"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find(" 4 frames, "), std::string::npos) << r.out;  // the 5th's completion row not yet written
  test::expect_same_trajectory(whole(), out);
}

// A fault the run never reaches changes nothing.
TEST_F(FaultPoints, AFaultNeverReachedChangesNothing) {
  const std::string out = test::scratch_dir("fault_points_unreached") + "/run.h5";
  const auto r = run_command(test::fault("events:1000000000000") + fresh(out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  test::expect_same_trajectory(whole(), out);
}

TEST(FaultPointsRefused, AMalformedFaultIsOneLineAndNothingIsWritten) {
  const std::string dir = test::scratch_dir("fault_points_refused");
  const std::string scene = test::write_file(dir, "gas.toml", test::kCoolingGasScene), out = dir + "/run.h5";
  for (const auto& [spec, needle] : std::vector<std::pair<std::string, std::string>>{
           {"nowhere", "COOLGAS_FAULT = 'nowhere': no point named 'nowhere' (POINT[:COUNT][:ACTION]"},
           {"dump-fram", "no point named 'dump-fram' (did you mean 'dump-frame'?)"},
           {"events:0", "COUNT '0' is not an integer >= 1"},
           {"events:1x", "COUNT '1x'"},
           {"dump-frame:2:STOP", "ACTION 'STOP' is not KILL, INT, TERM, HUP or WAIT"},
           {"events:1:INT:2", "more than three fields"}}) {
    test::expect_refused_with_one_line(run_command(test::fault(spec) + test::simulate(scene + " -o " + out)), needle,
                                       spec);
    EXPECT_FALSE(exists(out)) << spec;
  }
}

}  // namespace
}  // namespace coolgas
