// Stopping the set-up (placement, equilibration) at once on SIGINT/SIGTERM:
// the loops look at the run's interrupt flag every few thousand steps and
// throw SetupInterrupted; nothing has been written yet.
#pragma once
#include <csignal>
#include <stdexcept>

namespace coolgas {

struct SetupInterrupted : std::runtime_error {
  SetupInterrupted() : std::runtime_error("interrupted during set-up") {}
};

// nullptr: never interrupted.
using InterruptFlag = const volatile std::sig_atomic_t*;

inline void throw_if_interrupted(InterruptFlag interrupt) {
  if (interrupt && *interrupt) throw SetupInterrupted();
}

}  // namespace coolgas
