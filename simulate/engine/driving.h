// The driven gas: the white-noise (stochastic) thermostat of van Noije &
// Ernst (Granular Matter 1, 57 (1998)), discretised as kicks. An engine
// whose particles keep their masses (the elastic, inelastic and
// viscoelastic gases) is wrapped in a DrivenEngine, which runs it from kick
// to kick; the engine's own loop is untouched (a scene without driving is
// not wrapped at all).
//
// At each kick time t_k every particle is brought to t_k, each velocity
// component gets a Gaussian increment of variance s² (unit masses), the
// mean increment is subtracted (total momentum unchanged to round-off:
// zero from a generated start), and every event is predicted afresh
// (EngineBase::add_velocities). The variance gives the energy of the
// interval just ended, P (t_k − t_{k−1}) per particle in expectation:
// s² = 2 P (t_k − t_{k−1}) N / (d (N − 1)) (the mean's removal takes
// (N − 1)/N of the noise's energy). The next kick follows after `period`
// mean collision times, 1/ω_E(T), at the temperature T the kick left
// (common/geometry.h, Enskog's rate), or at T_P = (P / ω_E(1))^(2/3), where
// a collision time brings in T, if the gas is colder (a gas at rest is
// kicked too). The discretisation is thus the same fraction of a collision
// time whatever the power, and the dynamics keeps the symmetry of hard
// spheres with constant restitution: velocities ×λ, times ÷λ, power ×λ³ is
// the same trajectory (exactly, bit for bit, for λ a power of 2 and T ≥ T_P).
// How far this is from the continuous thermostat: docs/simulate.md, "Driven gas".
//
// The noise of kick k comes from its own generator, seeded from the run's
// seed and k (counter-based): the schedule (last kick, next kick, count) is
// all a checkpoint needs ("driving/schedule", data-schema/checkpoint.md).
#pragma once
#include <cstdint>
#include <memory>
#include <vector>

#include "common/geometry.h"
#include "simulate/engine/engine_base.h"
#include "simulate/engine/state_archive.h"

namespace coolgas {

struct Driving {
  double power = 0;   // energy injected per particle per unit time (m σ² ω0³)
  double period = 0;  // kick interval, in mean collision times (1/ω_E) at the gas's temperature
  std::uint64_t seed = 0;
  Geometry geometry{3};
};

// The kicks' clock: the last kick (or the start), the next, and how many so far.
struct KickSchedule {
  double previous = 0, next = 0;
  std::int64_t kicks = 0;
};

// For tests: each kick's time, the total momentum it left, and the kinetic
// energy per particle before and after it.
struct KickRecord {
  double time;
  Vec3 momentum;
  double energy_before, energy_after;
};

class DrivenEngine final : public EngineBase {
 public:
  // `engine` at its current time, the first kick one interval later.
  DrivenEngine(std::unique_ptr<EngineBase> engine, const Driving& driving);
  // `engine` restored from `state`, with the schedule `state` holds.
  DrivenEngine(std::unique_ptr<EngineBase> engine, const Driving& driving, const StateReader& state);

  // The inner engine's run_until, from kick to kick up to t_stop (a kick due
  // at t_stop itself is made): how the run is sliced changes nothing.
  RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) override;
  double now() const override { return engine_->now(); }
  std::size_t size() const override { return engine_->size(); }
  double box() const override { return engine_->box(); }
  const EngineCounters& counters() const override { return engine_->counters(); }
  Observables observables() const override { return engine_->observables(); }
  EngineFrame frame() const override { return engine_->frame(); }
  void save(StateWriter& out) const override;

  const KickSchedule& schedule() const { return schedule_; }
  void record_kicks(std::vector<KickRecord>* log) { log_ = log; }

 private:
  void kick();
  // The interval after a kick that left the gas with kinetic energy `energy` per particle.
  double interval(double energy) const;

  std::unique_ptr<EngineBase> engine_;
  Driving driving_;
  double density_, phi_;  // number density and covered fraction, for Enskog's rate
  KickSchedule schedule_;
  std::vector<KickRecord>* log_ = nullptr;
};

}  // namespace coolgas
