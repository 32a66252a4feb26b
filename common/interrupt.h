// Stopping a long computation at once on SIGINT/SIGTERM (Ctrl-C, kill, a
// batch system's pre-emption), shared by the simulator and every analysis
// tool that loops over many dumps, replicas or time steps.
//
// watch_interrupts() replaces the default action (death without a word) by
// a handler that only records the signal; the long loops look at the flag
// between units of work (a dump, a simplex iteration, a time step) and throw
// Interrupted, so that the tool ends within a fraction of a second with one
// line on stderr and exit code 3 (kExitInterrupted, common/tool_main.h), its
// outputs either complete or not written at all. Only a tool whose loops
// look at the flag may call watch_interrupts(): for any other, the default
// action is the right one.
#pragma once
#include <csignal>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "common/fault_point.h"

namespace coolgas {

// Points at the signal number once SIGINT or SIGTERM arrived, else at 0
// (nullptr: a computation that is never interrupted).
using InterruptFlag = const volatile std::sig_atomic_t*;

// Thrown by throw_if_interrupted; what() says where the work stopped and
// what was (not) written, e.g. "after 3 of 40 dumps; no table written".
struct Interrupted : std::runtime_error {
  Interrupted(int signal, const std::string& where);
  int signal;
};

// Installs the handler for SIGINT and SIGTERM (system calls are restarted,
// so an interrupted read or write is never half done). Also for a process
// started with the signals ignored (a shell's background job), so that a
// signal sent on purpose is never lost. SIGHUP (a dropped terminal or ssh
// session) is handled the same way, except in a process started with it
// ignored (nohup), which keeps ignoring it. The signals are unblocked: one
// sent before the process started, while they were blocked, is recorded at
// once (how tests interrupt a loop at its first look, without timing).
void watch_interrupts();

// The flag the handler sets (for loops that take an InterruptFlag).
InterruptFlag interrupt_flag();
// The signal received, or 0.
int interrupt_signal();
// "SIGINT", "SIGTERM", "SIGHUP" or "signal N".
std::string signal_name(int signal);

// Whether a signal has arrived: a loop's look at the flag, which a test's
// fault `interrupt-check` counts (common/fault_point.h: it raises a signal
// at the COUNT-th look, or waits there for one, so a test stops a loop in
// its middle without timing; the engines read the flag themselves, uncounted).
inline bool interrupted() {
  fault_point(FaultPoint::kInterruptCheck);
  return interrupt_signal() != 0;
}
// Throws Interrupted(signal, where) once a signal has arrived. (A loop whose
// message needs numbers builds it only when interrupted().)
inline void throw_if_interrupted(const char* where) {
  if (interrupted()) throw Interrupted(interrupt_signal(), where);
}
// The check of a loop whose table is written only when the loop is done:
// "after DONE of TOTAL UNITS; no table written".
void throw_if_interrupted(std::size_t done, std::size_t total, const char* units);
// The same stop for a signal that came inside a unit (a replica's own
// search), reported as a stop between units.
Interrupted interrupted_after(int signal, std::size_t done, std::size_t total, const char* units);

}  // namespace coolgas
