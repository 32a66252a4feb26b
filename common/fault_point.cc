#include "common/fault_point.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "common/did_you_mean.h"
#include "common/error.h"
#include "common/interrupt.h"

namespace coolgas {

// Everything here in fault_detail, so that a unity build's anonymous
// namespaces of other files never meet these names.
namespace fault_detail {
namespace {

struct SignalName {
  int signal;
  const char* name;
};
constexpr int kWait = 0;  // the WAIT action, among the signals
constexpr SignalName kActions[] = {
    {SIGKILL, "KILL"}, {SIGINT, "INT"}, {SIGTERM, "TERM"}, {SIGHUP, "HUP"}, {kWait, "WAIT"}};

struct Fault {
  std::int64_t count = 1;   // the passage that faults
  std::int64_t passed = 0;  // passages so far
  int signal = SIGKILL;     // or kWait
  std::string text;         // as given
  std::string ready;        // WAIT: the file to create
};
Fault g_fault;

[[noreturn]] void refuse(const std::string& value, const std::string& why) {
  throw InputError("COOLGAS_FAULT = '" + shown(value) + "': " + why +
                   " (POINT[:COUNT][:ACTION], a test's fault: docs/reliability.md)");
}

std::vector<std::string> fields_of(const std::string& s) {
  std::vector<std::string> fields(1);
  for (const char c : s) {
    if (c == ':')
      fields.emplace_back();
    else
      fields.back() += c;
  }
  return fields;
}

// The signals a WAIT ends on: the interrupts, whose handler records them
// (common/interrupt.h), and SIGCONT, "go on as if nothing happened".
constexpr int kWaitSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGCONT};
volatile std::sig_atomic_t g_continued = 0;
extern "C" void record_continue(int) { g_continued = 1; }

// WAIT: the ready file appears only once the signals are blocked, and they
// are unblocked only inside sigsuspend, so a signal sent as soon as the
// file is seen is never lost, however soon that is. (A file that cannot be
// created ends the program, with one line: a test must not wait forever.)
void wait_for_signal() {
  sigset_t watched, before;
  sigemptyset(&watched);
  for (const int s : kWaitSignals) sigaddset(&watched, s);
  sigprocmask(SIG_BLOCK, &watched, &before);
  struct sigaction cont {}, cont_before {};
  cont.sa_handler = record_continue;
  sigemptyset(&cont.sa_mask);
  sigaction(SIGCONT, &cont, &cont_before);
  // Said on stderr even under --quiet: a scheduler's log shows where the run
  // was held (tests/cli/slurm_cluster_test.sh looks for it).
  std::fprintf(stderr, "coolgas: fault: holding at COOLGAS_FAULT = '%s' until SIGINT, SIGTERM, SIGHUP or SIGCONT\n",
               g_fault.text.c_str());
  if (!g_fault.ready.empty()) {
    const int fd = ::open(g_fault.ready.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) {
      std::fprintf(stderr, "coolgas: COOLGAS_FAULT_READY = '%s': cannot create it: %s\n", g_fault.ready.c_str(),
                   std::strerror(errno));
      std::_Exit(kExitFailure);
    }
    ::close(fd);
  }
  sigset_t during = before;
  for (const int s : kWaitSignals) sigdelset(&during, s);
  while (interrupt_signal() == 0 && !g_continued) sigsuspend(&during);
  sigaction(SIGCONT, &cont_before, nullptr);
  sigprocmask(SIG_SETMASK, &before, nullptr);
}

// The fault happens: any action but KILL happens once and the program goes
// on (a signal's handler decides what follows).
void fire() {
  if (g_fault.signal != SIGKILL) armed = FaultPoint::kNone;
  if (g_fault.signal == kWait) wait_for_signal();
  else std::raise(g_fault.signal);
}

}  // namespace

void reached() {
  if (++g_fault.passed == g_fault.count) fire();
}

const char* arm() {
  const char* s = std::getenv("COOLGAS_FAULT");
  if (!s || !*s) return "";
  const std::string value = s;
  const std::vector<std::string> fields = fields_of(value);
  if (fields.size() > 3) refuse(value, "more than three fields");
  FaultPoint point = FaultPoint::kNone;
  for (const FaultPointName& p : kFaultPoints)
    if (fields[0] == p.name) point = p.point;
  if (point == FaultPoint::kNone) {
    std::vector<std::string> names;
    for (const FaultPointName& p : kFaultPoints) names.emplace_back(p.name);
    refuse(value, "no point named '" + shown(fields[0]) + "'" + did_you_mean(fields[0], names));
  }
  Fault f;
  if (fields.size() > 1) {
    const std::string& c = fields[1];
    char* end = nullptr;
    const long long n = c.empty() ? 0 : std::strtoll(c.c_str(), &end, 10);
    if (c.empty() || *end != '\0' || n < 1) refuse(value, "COUNT '" + shown(c) + "' is not an integer >= 1");
    f.count = n;
  }
  if (fields.size() > 2) {
    f.signal = -1;
    for (const SignalName& a : kActions)
      if (fields[2] == a.name) f.signal = a.signal;
    if (f.signal == -1) refuse(value, "ACTION '" + shown(fields[2]) + "' is not KILL, INT, TERM, HUP or WAIT");
  }
  if (f.signal == kWait) {
    const char* ready = std::getenv("COOLGAS_FAULT_READY");
    if (ready) f.ready = ready;
  }
  f.text = value;
  g_fault = f;
  armed = point;
  return g_fault.text.c_str();
}

std::int64_t events_left(std::int64_t done) {
  if (armed != FaultPoint::kEvents) return std::numeric_limits<std::int64_t>::max();
  return done < g_fault.count ? g_fault.count - done : 0;
}

void after_events(std::int64_t done) {
  if (armed == FaultPoint::kEvents && done >= g_fault.count) fire();
}

}  // namespace fault_detail

const char* arm_fault_from_environment() { return fault_detail::arm(); }
const char* armed_fault() { return fault_detail::g_fault.text.c_str(); }
std::int64_t fault_events_left(std::int64_t done) { return fault_detail::events_left(done); }
void fault_after_events(std::int64_t done) { fault_detail::after_events(done); }

}  // namespace coolgas
