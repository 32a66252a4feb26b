// The event-driven engine: hard spheres in a periodic box, advanced from
// collision to collision.
//
// Techniques (as in the fastest event-driven codes):
//   - cell grid (cell_grid.h): a particle looks for partners in 27 cells;
//     crossing into a new cell is an event of its own;
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
//     hot loop of an elastic scene contains no inelastic code.
//
// The runner sees the engine through EngineBase; make_engine() picks the
// instantiation once, at start-up.
#pragma once
#include <csignal>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/collision_rules.h"
#include "simulate/engine/event_calendar.h"
#include "simulate/engine/particles.h"

namespace coolgas {

struct EngineCounters {
  std::int64_t collisions = 0;   // collisions processed
  std::int64_t below_delta = 0;  // of which made elastic by the δ cut-off
  std::int64_t events = 0;       // all events: collisions, cell crossings, stale ones
  std::int64_t stale = 0;        // events found invalid when due
};

// Everything the partner search reads of a particle, in one cache line.
struct alignas(64) Motion {
  Vec3 r;                  // position at time t (wrapped into the box up to round-off)
  Vec3 v;                  // velocity
  double t;                // time at which r is valid
  std::uint32_t count;     // collisions since the last rebuild (lazy invalidation)
  std::int32_t next;       // next particle in the same cell (the cell grid's list link)
};
static_assert(sizeof(Motion) == 64, "one cache line per particle");
inline constexpr int kMotionStride = sizeof(Motion) / sizeof(double);  // doubles per record

struct CollisionRecord {
  int i, j;  // i < j
  double t;
};

// Inelastic collapse: infinitely many collisions in finite time (McNamara &
// Young 1992). Thrown when particles keep colliding without time advancing.
struct CollapseError : std::runtime_error {
  CollapseError(const std::string& what, double t) : std::runtime_error(what), time(t) {}
  double time;
};

enum class RunStatus {
  kReached,      // every event up to t_stop processed; now() == t_stop
  kEventBudget,  // max_events processed first; call again to go on
  kInterrupted,  // *interrupt became non-zero
};

// The check both engines make before each event: every 4096 events, whether
// the run must pause (interrupt flag set, or max_events processed since the
// run_until call, whose budget ends at `last_event`). Returns true and sets
// `status` if so.
inline bool pause_due(std::int64_t events, std::int64_t last_event, const volatile std::sig_atomic_t* interrupt,
                      RunStatus& status) {
  if ((events & 4095) != 0) return false;
  if (interrupt && *interrupt) status = RunStatus::kInterrupted;
  else if (events >= last_event) status = RunStatus::kEventBudget;
  else return false;
  return true;
}

class EngineBase {
 public:
  virtual ~EngineBase() = default;
  // Processes events in time order up to t_stop, at most max_events of them;
  // the interrupt flag is looked at every few thousand events. Stopping early
  // changes nothing: the same events follow. Throws CollapseError.
  virtual RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) = 0;
  // Brings every particle to now(), wraps positions into [0, L) and puts them
  // in id order; the next run_until() rebuilds the grid, the predictions and
  // the calendar from the particles alone. A dump is taken right after this,
  // so resuming from the dump rebuilds the identical state.
  virtual void synchronize() = 0;
  virtual double now() const = 0;
  virtual std::size_t size() const = 0;
  virtual double box() const = 0;
  // Read access for observables and dumps: the records and image counts, in
  // id order right after synchronize() (in between, in the engine's order).
  virtual const Motion* motion() const = 0;
  virtual const Image* images() const = 0;
  // A copy of the particles in the interchange format (tests, set-up).
  virtual Particles snapshot() const = 0;
  virtual const EngineCounters& counters() const = 0;
  // When set, every collision is appended (tests compare engines with it).
  virtual void record_collisions(std::vector<CollisionRecord>* log) = 0;
  // Calendar years started (a benchmark statistic).
  virtual std::int64_t calendar_years() const = 0;
  // Ballistic aggregation (aggregation_engine.h) changes the particles: per
  // slot (id order) the mass and diameter, and the id, -1 once the slot's
  // aggregate has merged into another. nullptr from engines whose particles
  // never change (unit mass and diameter, all present).
  virtual const double* masses() const { return nullptr; }
  virtual const double* diameters() const { return nullptr; }
  virtual const std::int32_t* ids() const { return nullptr; }
};

// Kinetic energy per particle and total momentum of the engine's particles,
// summed in id order with compensation (common/compensated_sum.h).
double kinetic_energy_per_particle(const EngineBase& e);
Vec3 total_momentum(const EngineBase& e);

template <class Rule>
class Engine final : public EngineBase {
 public:
  // Particles are taken as they are at time `now` (positions valid at now).
  Engine(Particles particles, const Rule& rule, double now, const EngineCounters& counters = {});

  RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) override;
  void synchronize() override;
  double now() const override { return now_; }
  std::size_t size() const override { return m_.size(); }
  double box() const override { return L_; }
  const Motion* motion() const override { return m_.data(); }
  const Image* images() const override { return image_.data(); }
  Particles snapshot() const override;
  const EngineCounters& counters() const override { return c_; }
  void record_collisions(std::vector<CollisionRecord>* log) override { log_ = log; }
  std::int64_t calendar_years() const override { return calendar_.years(); }
  // The positions at now(), wrapped, in id order; the engine is spent (only
  // destruction is left). Its other arrays are freed first, so the positions
  // never coexist with the whole engine (the set-up's memory peak).
  std::vector<Vec3> release_positions();

 private:
  void advance(int i);
  void rebuild();
  void order_by_space();
  void order_by_id();
  // A partner search in two halves (engine.cc): the non-empty cells around a
  // particle with the periodic shift of each (if any wraps), then the
  // contact times with their particles.
  struct Search {
    int heads[27], which[27], n;
    double shifts[27][3];
    bool wraps;
  };
  void start_search(int home, const int* lo, const int* hi, Search& s) const;
  void finish_search(const Vec3& ri, const Vec3& vi, const Search& s, double& best, int& partner) const;
  Event find_event(int i);
  Event finish_event(int i, const Search& s);
  Event earliest(int i, const Vec3& ri, const Vec3& vi, const Event& collision);
  Event cross(int i, int face);
  void collide(int i, int j);
  void note_collision_gap(int i, double gap, int partner);
  Vec3 image_shift(int from_cell, int to_cell) const;
  // The cells around c at offsets o[d] in [lo[d], hi[d]] (each within -1..1);
  // returns how many. If some wrap around the box (wraps), shifts holds the
  // periodic shift of each, else it is left untouched.
  int neighbour_cells(const CellCoord& c, const int* lo, const int* hi, int* cells, double (*shifts)[3],
                      bool& wraps) const;
  // Earliest contact of a particle (at now_, at ri with vi) with the particles
  // of one cell list starting at `first`, whose images are shifted by s;
  // updates best/code. The particle itself may be in the list: at distance 0
  // it never approaches.
  void scan_list(const Vec3& ri, const Vec3& vi, int first, const double* s, double& best, int& code) const;

  double L_;
  std::vector<Motion> m_;
  std::vector<Image> image_;
  std::vector<std::int32_t> id_;  // particle id of each internal index
  bool built_ = false;            // in space order, with grid, predictions and calendar
  Rule rule_;
  CellGrid grid_;
  EventCalendar calendar_;  // each particle's event: partner >= 0, or the cell face to cross (-1 - face)
  // For a particle whose event is a cell crossing: its earliest predicted
  // collision with the particles around (partner -1 and time +inf if none),
  // still valid at the crossing if that partner has not collided since. The
  // crossing then needs to search only the 9 cells that became neighbours,
  // not all 27 (crossings are about 40 % of all events).
  std::vector<Event> later_;
  std::vector<std::uint16_t> stall_;         // consecutive collisions without time advancing (dissipative rules)
  double now_;
  EngineCounters c_;
  std::vector<CollisionRecord>* log_ = nullptr;
};

}  // namespace coolgas
