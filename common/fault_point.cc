#include "common/fault_point.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
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
constexpr int kHold = -1;  // WAIT: no signal raised, the run holds until one comes
constexpr SignalName kSignals[] = {
    {SIGKILL, "KILL"}, {SIGINT, "INT"}, {SIGTERM, "TERM"}, {SIGHUP, "HUP"}, {kHold, "WAIT"}};

struct Fault {
  std::int64_t count = 1;   // the passage that faults
  std::int64_t passed = 0;  // passages so far
  int signal = SIGKILL;
  std::string text;  // as given
};
Fault g_fault;

[[noreturn]] void refuse(const std::string& value, const std::string& why) {
  throw InputError("COOLGAS_FAULT = '" + shown(value) + "': " + why +
                   " (POINT[:COUNT][:SIGNAL], a test's fault: docs/reliability.md)");
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

// WAIT: the run holds until SIGINT, SIGTERM or SIGHUP arrives (the handler
// of common/interrupt.h records it), then goes on to handle it. The signals
// are blocked from the test of the flag to the wait, which unblocks them, so
// that one arriving in between is not missed. The line is written even under
// --quiet: it is how a test knows the run is there.
void hold() {
  sigset_t stops, before;
  sigemptyset(&stops);
  for (const int s : {SIGINT, SIGTERM, SIGHUP}) sigaddset(&stops, s);
  sigprocmask(SIG_BLOCK, &stops, &before);
  std::fprintf(stderr, "coolgas-simulate: fault: holding at COOLGAS_FAULT = '%s' until SIGINT, SIGTERM or SIGHUP\n",
               g_fault.text.c_str());
  while (!interrupted()) sigsuspend(&before);
  sigprocmask(SIG_SETMASK, &before, nullptr);
}

// The fault happens: a signal other than SIGKILL is raised once (or WAIT
// holds once) and the program goes on (the signal's handler decides what follows).
void fire() {
  if (g_fault.signal != SIGKILL) armed = FaultPoint::kNone;
  if (g_fault.signal == kHold)
    hold();
  else
    std::raise(g_fault.signal);
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
    f.signal = 0;
    for (const SignalName& sig : kSignals)
      if (fields[2] == sig.name) f.signal = sig.signal;
    if (f.signal == 0) refuse(value, "SIGNAL '" + shown(fields[2]) + "' is not KILL, INT, TERM, HUP or WAIT");
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
std::int64_t fault_events_left(std::int64_t done) { return fault_detail::events_left(done); }
void fault_after_events(std::int64_t done) { fault_detail::after_events(done); }

}  // namespace coolgas
