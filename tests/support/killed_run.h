// A run killed halfway, as the resume tests of each kind of run make it.
#pragma once
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "tests/support/fault_points.h"
#include "tests/support/run_command.h"
#include "tests/support/same_trajectory.h"
#include "tests/support/simulate_cli.h"

namespace coolgas::test {

// Runs `command` (a coolgas-simulate command line) with a checkpoint after
// every slice of events and kills it halfway through the collisions of
// `whole`, the uninterrupted run of the same scene.
inline void kill_halfway(const std::string& command, const std::string& whole) {
  const auto stopped =
      run_command("COOLGAS_CHECKPOINT_INTERVAL=0 " + fault(events_at(0.5, collisions_of(whole))) + command);
  EXPECT_EQ(stopped.exit_code, kKilled) << stopped.err;
}

// Kills `command`, which writes `out`, halfway; resumes it; expects `whole`'s
// trajectory bit for bit.
inline void expect_killed_run_resumes_bit_for_bit(const std::string& command, const std::string& out,
                                                  const std::string& whole) {
  kill_halfway(command, whole);
  const auto resumed = run_command(simulate("--resume " + out));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  expect_same_trajectory(whole, out);
}

// Kills `command`, which writes `out`, halfway; deletes its checkpoint;
// resumes it from its last dump and expects a file coolgas-validate accepts.
inline void expect_killed_run_resumes_from_its_last_dump(const std::string& command, const std::string& out,
                                                         const std::string& whole) {
  kill_halfway(command, whole);
  std::remove((out + ".checkpoint").c_str());
  const auto resumed = run_command(simulate("--resume " + out));
  ASSERT_EQ(resumed.exit_code, 0) << resumed.err;
  const auto v = run_command(bin("coolgas-validate") + " " + out);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
}

}  // namespace coolgas::test
