// What the runner sees of an engine: advance it, read its observables and a
// frame of the particles at the current time, save its exact state. None of
// these reads changes the engine: observation never perturbs the trajectory.
#pragma once
#include <csignal>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "simulate/engine/particles.h"

namespace coolgas {

class StateWriter;

struct EngineCounters {
  std::int64_t collisions = 0;   // collisions processed (aggregation: merges)
  std::int64_t below_delta = 0;  // of which made elastic by the δ cut-off
  std::int64_t events = 0;       // all events: collisions, cell crossings, stale ones
  std::int64_t stale = 0;        // events found invalid when due
};

// Why an engine cannot go on.
enum class StopReason {
  kInelasticCollapse,  // infinitely many collisions in finite time (McNamara & Young 1992)
  kAggregateTooLarge,  // an aggregate as wide as half the box (the minimum-image limit)
};

// Thrown by run_until() when the engine cannot go on; its state stays
// readable (observables, frame) at time `time`.
struct RunStopped : std::runtime_error {
  RunStopped(StopReason r, const std::string& what, double t) : std::runtime_error(what), reason(r), time(t) {}
  StopReason reason;
  double time;
};

enum class RunStatus {
  kReached,      // every event up to t_stop processed; now() == t_stop
  kEventBudget,  // max_events processed first; call again to go on
  kInterrupted,  // *interrupt became non-zero
};

// The check both engines make before each event: whether max_events have
// been processed since the run_until call (its budget ends at `last_event`),
// or, every 4096 events, whether the interrupt flag is set. Returns true and
// sets `status` if the run must pause. `every_4096` runs on that rare path
// too (before the flag is read), so a check per slice of events costs the
// hot loop nothing.
template <class Tick>
inline bool pause_due(std::int64_t events, std::int64_t last_event, const volatile std::sig_atomic_t* interrupt,
                      RunStatus& status, Tick&& every_4096) {
  if (events >= last_event) {
    status = RunStatus::kEventBudget;
    return true;
  }
  if ((events & 4095) != 0) return false;
  every_4096();
  if (!interrupt || !*interrupt) return false;
  status = RunStatus::kInterrupted;
  return true;
}
inline bool pause_due(std::int64_t events, std::int64_t last_event, const volatile std::sig_atomic_t* interrupt,
                      RunStatus& status) {
  return pause_due(events, last_event, interrupt, status, [] {});
}

// The aggregation observables (absent for engines whose particles never change).
struct AggregateStats {
  std::int64_t aggregates = 0;
  double mean_mass = 0, largest_mass = 0;
};

struct Observables {
  Observables(double t, const EngineCounters& c) : time(t), collisions(c.collisions), below_delta(c.below_delta) {}
  double time = 0;
  std::int64_t collisions = 0, below_delta = 0;
  double kinetic_energy = 0;  // Σ ½ m v² / N over the N initial particles, summed in id order with compensation
  Vec3 momentum;              // Σ m v, likewise
  std::optional<double> rotational_energy;  // Σ ½ I ω² / N likewise: rough particles only
  std::vector<double> species_energy;       // a mixture's Σ ½ m v² / N_s per species s; else empty
  std::optional<AggregateStats> aggregates;
};

// The particles at the engine's current time, in id order: positions
// advanced to that time and wrapped into [0, L), image counts, velocities.
// id, mass and diameter are filled only by engines whose particles change
// (aggregation: per slot; id -1 and mass 0 in an empty slot).
struct EngineFrame {
  EngineFrame(double t, const EngineCounters& c) : time(t), collisions(c.collisions), below_delta(c.below_delta) {}
  double time = 0;
  std::int64_t collisions = 0, below_delta = 0;
  std::vector<Vec3> position, velocity;
  std::vector<Vec3> angular_velocity;  // rough particles only
  std::vector<std::int32_t> species;   // a mixture's only
  std::vector<Image> image;
  std::vector<std::int32_t> id;
  std::vector<double> mass, diameter;
};

class EngineBase {
 public:
  virtual ~EngineBase() = default;
  // Processes events in time order up to t_stop, but no more than max_events
  // of them (the budget is checked before every event); the interrupt flag is
  // looked at every 4096 events. Stopping early, for any reason, changes
  // nothing: the same events follow. Throws RunStopped.
  virtual RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) = 0;
  virtual double now() const = 0;
  virtual std::size_t size() const = 0;
  virtual double box() const = 0;
  virtual const EngineCounters& counters() const = 0;
  virtual Observables observables() const = 0;
  virtual EngineFrame frame() const = 0;
  // Every field the engine's future depends on (state_archive.h); the
  // engine's restoring constructor reads them back.
  virtual void save(StateWriter& out) const = 0;
  // Every particle brought to now(), dv[id] added to the velocity of
  // particle id, and every event predicted afresh: a kick of the driven gas
  // (driving.h), between events, never inside run_until's loop. Engines
  // whose particles merge do not offer it (std::logic_error).
  virtual void add_velocities(const std::vector<Vec3>& /*dv*/) {
    throw std::logic_error("this engine's particles cannot be kicked");
  }
};

}  // namespace coolgas
