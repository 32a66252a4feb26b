// Test-only faults at named points: COOLGAS_FAULT=POINT[:COUNT][:ACTION]
// makes a coolgas program act at the COUNT-th passage (default 1) of POINT:
// - KILL (the default): stop as if sent SIGKILL there: raise(SIGKILL), so
//   nothing is flushed and no handler runs, and the exit status is a
//   killed process's;
// - INT, TERM or HUP: raise that signal, once; its handler
//   (common/interrupt.h) takes over as for a signal from outside;
// - WAIT: say so on stderr, create the file COOLGAS_FAULT_READY names (if
//   it names one) and sleep there until
//   SIGINT, SIGTERM or SIGHUP reaches the handler (then go on, and stop at
//   the next look at the flag), SIGCONT comes (go on as if nothing
//   happened) or a signal ends the process: a test polls for the file,
//   then acts (reads the file, starts a second writer, sends a signal)
//   while the program is known to be at that point; a scheduler's signal or
//   kill finds a held run at a known point whenever it comes
//   (tests/cli/slurm_cluster_test.sh).
// This lets a test act at a chosen moment of a program's life instead of at
// a moment of wall time (docs/reliability.md, "Faults at named points").
//
// The variable is read once, by arm_fault_from_environment() (every tool's
// run_tool, common/tool_main.h). A point costs one comparison with a global
// where it is reached, on a path that writes or reads a file or between
// units of a loop's work; `events` only bounds the run driver's slice of
// events, so the engine's loop is untouched. The points are listed here, once.
#pragma once
#include <cstdint>

namespace coolgas {

enum class FaultPoint : std::uint8_t {
  kNone,
  kEvents,            // after the COUNT-th event of the run (the run driver's slice ends there)
  kCheckpointWrite,   // a checkpoint partly written under its temporary name
  kCheckpointRename,  // a checkpoint synced under its temporary name, not renamed
  kReplaceRename,     // a file's replacement synced under its temporary name, not renamed
  kConvert,           // converting an earlier version's file, before its COUNT-th object
  kResumeClaimed,     // a resume holding the file's lock, its recorded end covered
  kResumeReopened,    // a resume with the file open for appending, an interrupted burst dropped
  kDumpFrame,         // a dump's rows written, nothing flushed
  kDumpFlushed,       // a dump's rows flushed, its completion row not yet written
  kEquilibration,     // the set-up's equilibration after its COUNT-th slice of events
  kInterruptCheck,    // a loop's COUNT-th look at the interrupt flag (interrupted(), common/interrupt.h)
};

struct FaultPointName {
  FaultPoint point;
  const char* name;  // as COOLGAS_FAULT spells it
};
inline constexpr FaultPointName kFaultPoints[] = {
    {FaultPoint::kEvents, "events"},
    {FaultPoint::kCheckpointWrite, "checkpoint-write"},
    {FaultPoint::kCheckpointRename, "checkpoint-rename"},
    {FaultPoint::kReplaceRename, "replace-rename"},
    {FaultPoint::kConvert, "convert"},
    {FaultPoint::kResumeClaimed, "resume-claimed"},
    {FaultPoint::kResumeReopened, "resume-reopened"},
    {FaultPoint::kDumpFrame, "dump-frame"},
    {FaultPoint::kDumpFlushed, "dump-flushed"},
    {FaultPoint::kEquilibration, "equilibration"},
    {FaultPoint::kInterruptCheck, "interrupt-check"},
};

namespace fault_detail {
inline FaultPoint armed = FaultPoint::kNone;
void reached();
}  // namespace fault_detail

// Reads COOLGAS_FAULT (unset or empty: no fault) and, for WAIT,
// COOLGAS_FAULT_READY. InputError naming the variable when it is malformed.
// Returns the text of an armed fault, or "".
const char* arm_fault_from_environment();
// The text of the armed fault, or "" (for a program's note that it runs one).
const char* armed_fault();

// The named point `p`: nothing unless it is armed.
inline void fault_point(FaultPoint p) {
  if (fault_detail::armed == p) [[unlikely]]
    fault_detail::reached();
}

// For the run driver, whose slices of events end where an `events` fault is
// due: the events still allowed after `done` events of the run (a large
// number when no such fault is armed), and the point itself, reached once
// `done` events were processed.
std::int64_t fault_events_left(std::int64_t done);
void fault_after_events(std::int64_t done);

}  // namespace coolgas
