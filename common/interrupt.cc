#include "common/interrupt.h"

namespace coolgas {

namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void record_signal(int sig) { g_signal = sig; }

}  // namespace

Interrupted::Interrupted(int signal, const std::string& where)
    : std::runtime_error("interrupted by " + signal_name(signal) + " " + where), signal(signal) {}

void watch_interrupts() {
  struct sigaction sa {};
  sa.sa_handler = record_signal;
  sa.sa_flags = SA_RESTART;
  sigemptyset(&sa.sa_mask);
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  // A hang-up (a dropped ssh session or terminal) stops the work like
  // SIGINT, unless the process was started to ignore it (nohup): then it
  // goes on ignoring it, as its user asked.
  struct sigaction hup {};
  const bool watch_hup = sigaction(SIGHUP, nullptr, &hup) == 0 && hup.sa_handler != SIG_IGN;
  if (watch_hup) sigaction(SIGHUP, &sa, nullptr);
  // A process started with the signals blocked (a launcher's mask, which
  // exec keeps) would never see them: they are unblocked, and one already
  // pending is recorded at once, so the first look at the flag stops the work.
  sigset_t set;
  sigemptyset(&set);
  sigaddset(&set, SIGINT);
  sigaddset(&set, SIGTERM);
  if (watch_hup) sigaddset(&set, SIGHUP);
  sigprocmask(SIG_UNBLOCK, &set, nullptr);
}

InterruptFlag interrupt_flag() { return &g_signal; }

int interrupt_signal() { return g_signal; }

void throw_if_interrupted(std::size_t done, std::size_t total, const char* units) {
  if (interrupted()) throw interrupted_after(interrupt_signal(), done, total, units);
}

Interrupted interrupted_after(int signal, std::size_t done, std::size_t total, const char* units) {
  return Interrupted(signal, "after " + std::to_string(done) + " of " + std::to_string(total) + " " + units +
                                 "; no table written");
}

std::string signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "signal " + std::to_string(signal);
  }
}

}  // namespace coolgas
