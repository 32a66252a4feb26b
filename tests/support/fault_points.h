// Helpers for the tests that stop coolgas-simulate at a named point instead
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
