// Helpers for the tests that stop a coolgas program at a named point instead
// of at a moment of wall time (common/fault_point.h): the same stop on every
// machine, however loaded.
#pragma once
#include <algorithm>
#include <cstdint>
#include <string>

#include "common/hdf5_file.h"

namespace coolgas::test {

// A killed process's exit code (as run_command reports it).
inline constexpr int kKilled = 128 + 9;

// The environment that arms a fault, to put before a command:
// fault("dump-frame:3") is "COOLGAS_FAULT=dump-frame:3 ".
inline std::string fault(const std::string& spec) { return "COOLGAS_FAULT=" + spec + " "; }

// The environment that makes a program wait at a point until a signal
// comes, after creating the file `ready`: waiting_at("events:100", R) is
// "COOLGAS_FAULT=events:100:WAIT COOLGAS_FAULT_READY=R ".
inline std::string waiting_at(const std::string& point, const std::string& ready) {
  return "COOLGAS_FAULT=" + point + ":WAIT COOLGAS_FAULT_READY=" + ready + " ";
}

// The longest a test waits for a program to reach its point: only a hang
// takes this long (a loaded machine takes seconds), and it stays below
// ctest's limit of a test (tests/CMakeLists.txt), so the test fails with a
// message of its own.
inline constexpr int kHangSeconds = 240;

// Shell: runs `command` (a program with a WAIT fault writing `ready`, and
// its redirections) in the background as $pid, waits until `ready` exists,
// then runs `then` (which acts on $pid: a signal, a second program), and
// waits for $pid; the shell's exit code is the program's. A program that
// ends without reaching its point is not waited for; one that never reaches
// it within kHangSeconds is killed, with "never reached its point" on stderr.
inline std::string when_ready(const std::string& command, const std::string& ready, const std::string& then) {
  return command + " & pid=$!; n=0; while [ ! -e " + ready + " ] && [ $n -lt " + std::to_string(10 * kHangSeconds) +
         " ] && kill -0 $pid 2>/dev/null; do sleep 0.1; n=$((n+1)); done; if [ -e " + ready + " ]; then " + then +
         "; else echo 'never reached its point' >&2; kill -KILL $pid; fi; wait $pid";
}

// The collisions of a run's file up to its last observation. A run has at
// least as many events, so a fault at a fraction of them lands inside it.
inline std::int64_t collisions_of(const std::string& path) {
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle c = h5::open_dataset(f.id(), "observables/collisions/value");
  const auto values = h5::read_all<std::int64_t>(c.id());
  return values.empty() ? 0 : values.back();
}

// "events:K[:SIGNAL]" with K that fraction of `collisions` (at least 1).
inline std::string events_at(double fraction, std::int64_t collisions, const std::string& signal = "") {
  const auto k = std::max<std::int64_t>(1, std::int64_t(fraction * double(collisions)));
  return "events:" + std::to_string(k) + (signal.empty() ? "" : ":" + signal);
}

}  // namespace coolgas::test
