#include "simulate/engine/driving.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "common/compensated_sum.h"
#include "common/random.h"

namespace coolgas {

namespace {

// SplitMix64's finaliser: a bijection of 64-bit words that mixes every bit.
std::uint64_t mix(std::uint64_t z) {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// The seed of kick k's generator: the run's seed and k hashed together (a
// stream apart from the start's, which is seeded with the run's seed itself;
// consecutive seeds of Random overlap, hashed ones do not).
std::uint64_t kick_seed(std::uint64_t seed, std::int64_t k) {
  return mix(mix(seed ^ 0x6a09e667f3bcc909ULL) + std::uint64_t(k));
}

}  // namespace

DrivenEngine::DrivenEngine(std::unique_ptr<EngineBase> engine, const Driving& driving)
    : engine_(std::move(engine)), driving_(driving) {
  const double n = double(engine_->size()), L = engine_->box();
  density_ = n / driving_.geometry.box_measure(L);
  phi_ = driving_.geometry.covered_fraction(n, L);
  schedule_.previous = engine_->now();
  schedule_.next = schedule_.previous + interval(engine_->observables().kinetic_energy);
}

DrivenEngine::DrivenEngine(std::unique_ptr<EngineBase> engine, const Driving& driving, const StateReader& in)
    : DrivenEngine(std::move(engine), driving) {
  const auto s = in.get_value<KickSchedule>("driving/schedule");
  const double now = engine_->now();
  if (!(std::isfinite(s.previous) && std::isfinite(s.next) && s.previous <= now && now <= s.next && s.kicks >= 0))
    in.fail("driving/schedule: the last kick (t = " + std::to_string(s.previous) + ") and the next (t = " +
            std::to_string(s.next) + ") must be finite around now = " + std::to_string(now) + ", the count >= 0");
  schedule_ = s;
}

void DrivenEngine::save(StateWriter& out) const {
  engine_->save(out);
  out.put_value("driving/schedule", schedule_);
}

RunStatus DrivenEngine::run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) {
  const std::int64_t first = engine_->counters().events;
  const auto budget_left = [&] { return max_events - (engine_->counters().events - first); };
  while (schedule_.next <= t_stop) {
    const RunStatus status = engine_->run_until(schedule_.next, budget_left(), interrupt);
    if (status != RunStatus::kReached) return status;
    kick();
  }
  return engine_->run_until(t_stop, budget_left(), interrupt);
}

void DrivenEngine::kick() {
  const std::size_t n = engine_->size();
  const Geometry& g = driving_.geometry;
  const double elapsed = schedule_.next - schedule_.previous;
  // Every product and quotient here scales exactly with a power of 2 of the
  // power, the times and the velocities (the symmetry of driving.h).
  const double s = std::sqrt(2.0 * driving_.power * elapsed * double(n) / (double(g.d()) * double(n - 1)));
  Random rng(kick_seed(driving_.seed, schedule_.kicks));
  std::vector<Vec3> dv(n);
  CompensatedSum sum[3];
  for (Vec3& v : dv)
    for (int a = 0; a < 3; ++a)
      if (g.spans(a)) {  // the axes beyond the dimension stay 0
        v[a] = s * rng.normal();
        sum[a].add(v[a]);
      }
  for (int a = 0; a < 3; ++a) {
    const double mean = sum[a].value() / double(n);
    for (Vec3& v : dv) v[a] -= mean;
  }
  const double before = log_ ? engine_->observables().kinetic_energy : 0;
  engine_->add_velocities(dv);
  const Observables o = engine_->observables();
  ++schedule_.kicks;
  schedule_.previous = schedule_.next;
  schedule_.next = schedule_.previous + interval(o.kinetic_energy);
  if (log_) log_->push_back({schedule_.previous, o.momentum, before, o.kinetic_energy});
}

double DrivenEngine::interval(double energy) const {
  const Geometry& g = driving_.geometry;
  const double T = energy / g.energy_per_temperature();
  // P = ω_E(T_P) T_P, with ω_E ∝ √T.
  const double T_P = std::pow(driving_.power / g.enskog_rate(density_, phi_, 1.0), 2.0 / 3.0);
  return driving_.period / g.enskog_rate(density_, phi_, std::max(T, T_P));
}

}  // namespace coolgas
