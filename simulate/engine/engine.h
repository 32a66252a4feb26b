// The event-driven engine: hard spheres in a periodic box, advanced from
// collision to collision.
//
// Techniques (as in the fastest event-driven codes):
//   - cell grid (cell_grid.h): a particle looks for partners in 27 cells;
//     crossing into a new cell is an event of its own; cells are one
//     diameter wide, except in a dilute gas (phi < 0.033), where they are
//     one mean spacing wide (engine.cc);
//   - one scheduled event per particle, the earliest of its predicted
//     collisions and its next cell crossing (the earliest collision is kept
//     too, so a crossing searches only the 9 new neighbour cells); events are
//     invalidated lazily:
//     each particle counts its collisions, an event remembers its partner's
//     count when predicted, and a mismatch when it comes due means "stale,
//     predict again";
//   - an O(1) event calendar (event_calendar.h) whose bucket width adapts;
//   - lazy positions: a particle is moved only at its own events;
//   - memory laid out for the partner search, which is bound by memory
//     latency: what it reads of a candidate (position, velocity, own time,
//     collision count, cell link) sits in one 64-byte record, so a candidate
//     costs one cache miss instead of four; every other field is an array of
//     its own (structure of arrays). Particles are renumbered internally in
//     the Morton order of their cells at every rebuild (spatial_order.h), so
//     neighbours in space are neighbours in memory. Measured in
//     tests/bench/engine_bench.cc.
//   - the collision rule is a template parameter (collision_rules.h), so the
//     hot loop of an elastic scene contains no inelastic code;
//   - rough spheres are a rule of their own (RoughRule): only its engines
//     keep spins, an array apart from the records (the partner search never
//     reads them; a collision turns them), so a smooth scene's engine is
//     the one it was;
//   - so are mixtures of sizes and masses (MixtureRule): only its engines
//     keep a species per particle, a byte array beside the records that
//     their partner search reads for each pair's contact distance, with
//     cells as wide as the largest particle;
//   - so is the dimension D: 3 (spheres in a periodic cube) or 2 (disks in a
//     periodic square). A 2D particle keeps the same record, with z and v_z
//     exactly 0 forever (every z term of a prediction or a collision is then
//     an exact 0); the grid is one layer of cells and a search walks the 9
//     cells around instead of 27. The record is one cache line either way, so
//     dropping z would save no memory traffic, and the 3D engine's code is
//     the same as before D existed. D = 1 is hard rods on a periodic ring
//     the same way: y, z, v_y and v_z exactly 0, one row of cells, the 3
//     cells around searched (rods never pass each other, so a rod's
//     partners are its two ring neighbours, which the cells find).
//
// The runner sees the engine through EngineBase (engine_base.h);
// make_engine() picks the instantiation once, at start-up.
//
// Rebuilds (every particle moved to now, renumbered along the Morton curve,
// grid, predictions and calendar made afresh) happen on the engine's own
// schedule only: at construction, and every kCollisionsPerParticlePerRebuild
// (200, engine.cc) collisions per particle, so that locality does not decay
// in a long run.
// Nothing the runner does (observables, frames, checkpoints, how run_until is
// sliced) moves a particle or changes a prediction.
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "common/geometry.h"
#include "simulate/engine/cell_grid.h"
#include "simulate/engine/collision_rules.h"
#include "simulate/engine/engine_base.h"
#include "simulate/engine/event_calendar.h"
#include "simulate/engine/motion.h"
#include "simulate/engine/particles.h"
#include "simulate/engine/state_archive.h"

namespace coolgas {

struct CollisionRecord {
  int i, j;  // i < j
  double t;
};

// The scalars of an engine's exact state, as one checkpoint record.
struct EngineScalars {
  double L, now;
  std::int64_t next_rebuild;
  EngineCounters counters;
};

// Where the check that simulated time advances last looked (engine.cc,
// watch_time()): the event count and the time then.
struct TimeWatch {
  std::int64_t events;
  double time;
};

template <class Rule, int D = 3>
class Engine final : public EngineBase {
  static_assert(D >= 1 && D <= 3, "the engine simulates rods (D = 1), disks (D = 2) or spheres (D = 3)");

 public:
  // Particles are taken as they are at time `now` (positions valid at now).
  Engine(Particles particles, const Rule& rule, double now, const EngineCounters& counters = {});
  // The engine whose exact state save() wrote (the rule itself is not saved;
  // nor is D: a state of the other dimension is refused, its grid mismatching).
  Engine(const Rule& rule, const StateReader& state);

  RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) override;
  double now() const override { return now_; }
  std::size_t size() const override { return m_.size(); }
  double box() const override { return L_; }
  const EngineCounters& counters() const override { return c_; }
  Observables observables() const override;
  EngineFrame frame() const override;
  void save(StateWriter& out) const override;
  void add_velocities(const std::vector<Vec3>& dv) override;

  // For tests: when set, every collision is appended.
  void record_collisions(std::vector<CollisionRecord>* log) { log_ = log; }
  // For benchmarks: calendar years started.
  std::int64_t calendar_years() const { return calendar_.years(); }
  // The positions at now(), wrapped, in id order; the engine is spent (only
  // destruction is left). Its other arrays are freed first, so the positions
  // never coexist with the whole engine (the set-up's memory peak).
  std::vector<Vec3> release_positions();

 private:
  void advance(int i);
  void move_all_to_now();
  double rotational_energy() const;
  void rebuild();
  void order_by_space();
  void order_by_id();
  std::vector<std::int32_t> slot_of_id() const;
  // A partner search in two halves (engine.cc): the non-empty cells around a
  // particle with the periodic shift of each (if any wraps), then the
  // contact times with their particles.
  struct Search {
    int heads[27], which[27], n;
    double shifts[27][3];
    bool wraps;
  };
  void start_search(int home, const int* lo, const int* hi, Search& s) const;
  void finish_search(const Vec3& ri, const Vec3& vi, double ai, const Search& s, double& best, int& partner) const;
  Event find_event(int i);
  Event finish_event(int i, const Search& s);
  Event earliest(int i, const Vec3& ri, const Vec3& vi, const Event& collision);
  Event cross(int i, int face);
  void collide(int i, int j);
  void note_collision_gap(int i, double gap, int partner);
  void watch_time();
  void check_records(const StateReader& in) const;
  Vec3 image_shift(int from_cell, int to_cell) const;
  // Earliest contact of a particle (at now_, at ri with vi) with the particles
  // of one cell list starting at `first`, whose images are shifted by s;
  // updates best/code. The particle itself may be in the list: at distance 0
  // it never approaches.
  // ai: the particle's radius (read by mixture engines only; 1/2 otherwise).
  void scan_list(const Vec3& ri, const Vec3& vi, double ai, int first, const double* s, double& best,
                 int& code) const;
  // Particle i's radius and mass: 1/2 and 1 unless the rule is a mixture's.
  double radius_of(int i) const;
  double mass_of(int i) const;
  std::vector<double> species_energy() const;

  double L_;
  std::vector<Motion> m_;
  std::vector<Image> image_;
  std::vector<std::int32_t> id_;  // particle id of each internal index
  std::vector<Vec3> omega_;       // angular velocities (rough rules only; else empty)
  std::vector<std::uint8_t> species_;  // each particle's species (mixture rules only; else empty)
  Rule rule_;
  CellGrid grid_;
  EventCalendar calendar_;  // each particle's event
  // For a particle whose event is a cell crossing: its earliest predicted
  // collision with the particles around (no event if none), still valid at
  // the crossing if that partner has not collided since. The crossing then
  // needs to search only the 9 cells that became neighbours, not all 27
  // (crossings are about 40 % of all events).
  std::vector<Event> later_;
  std::vector<std::uint32_t> stall_;  // consecutive collisions without time advancing (dissipative rules)
  double now_;
  EngineCounters c_;
  std::int64_t next_rebuild_ = 0;  // the collision count at which the next rebuild is due
  TimeWatch watch_{0, 0};          // the start of the current window of watch_time()
  std::vector<CollisionRecord>* log_ = nullptr;
};

}  // namespace coolgas
