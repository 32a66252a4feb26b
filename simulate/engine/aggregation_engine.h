// Ballistic aggregation (the paper's BA): spheres move ballistically and two
// aggregates that touch become one, at their centre of mass, with the summed
// mass and volume (diameter (d1³ + d2³)^{1/3}) and the momentum-conserving
// velocity. In 2D (disks in a periodic square, z and v_z exactly 0 as in
// Engine<Rule, 2>) areas add: diameter (d1² + d2²)^{1/2}; in 1D (rods on a
// ring, y = z = 0) lengths add: diameter d1 + d2, the mass staying
// proportional to the length. Two touching rods span exactly [x1 - d1/2,
// x2 + d2/2], and their merged rod, centred at the centre of mass, spans the
// same: a 1D merge never overlaps a third rod, so chains arise only from
// rods that touch at the same instant. The dimension is a
// member, not a template parameter: this engine's cost is its searches over
// aggregates of many sizes, not a hot loop a branch would slow. The new aggregate may overlap others: those merge too, at the
// same instant, until no pair overlaps (chain aggregation), across periodic
// images. Masses are in particle masses, diameters in particle diameters.
//
// An event-driven engine of its own (particles change in number and size),
// built from the same parts as Engine<Rule>: the cell grid (cell_grid.h), the
// event calendar (event_calendar.h), the contact time (pair_prediction.h with
// σ = (d_i + d_j)/2), one event per aggregate, lazy positions and lazy
// invalidation by counters. The grid is sized for typical aggregates, not for
// the largest: cells about one aggregate wide on average. The aggregates
// wider than a cell ("large") are indexed apart in coarse
// cells of block³ fine cells (large_aggregate_index.h): a large aggregate's
// search looks as many fine cells out as its reach (aggregation_reach.h),
// and every search looks for large partners of each size class in the
// coarse cells within the reach a pair with that class can need, at the
// periodic images their fine cells allow. So the size spread costs the few
// large aggregates, not every search. The grid is rebuilt, with wider cells,
// when aggregates have become four times fewer than cells.
//
// The limit: aggregates may grow until the largest diameter reaches L/2.
// Below it every contact distance (d_i + d_j)/2 is below L/2, so two
// aggregates touch through one periodic image only, which is then their
// minimum image: the merge's centre of mass and the chain's overlap test by
// minimum image are exact. Beyond it an aggregate could touch another
// through two images at once, or itself; the run stops there (RunStopped).
// The cells impose nothing: a reach wider than the box visits every image.
//
// Ids are stable: a merge keeps the smaller id and empties the other
// aggregate's slot (id -1, mass and diameter 0, position and velocity 0);
// frames list every id, an absent one as such an empty entry. The slots are
// renumbered in the order of space at each grid rebuild (order_in_space),
// which changes where an aggregate is stored but never its id, nor which
// aggregates merge when: merges, frames and observables are those of ids.
#pragma once
#include <memory>
#include <vector>

#include "simulate/engine/cell_grid.h"
#include "simulate/engine/engine.h"
#include "simulate/engine/engine_base.h"
#include "simulate/engine/event_calendar.h"
#include "simulate/engine/large_aggregate_index.h"
#include "simulate/engine/motion.h"
#include "simulate/engine/state_archive.h"

namespace coolgas {

// Mass, diameter and presence of each slot (set-up and resume).
struct AggregateState {
  std::vector<double> mass;
  std::vector<double> diameter;
  std::vector<std::int32_t> id;  // i, or -1 for an empty slot

  static AggregateState unit_spheres(std::size_t n);  // n particles of mass 1, diameter 1
  // A mixture's particles, each of its species' mass and diameter (index: species).
  static AggregateState of_species(const std::vector<std::uint8_t>& species, const std::vector<double>& mass,
                                   const std::vector<double>& diameter);
};

// The scalars of the aggregation engine's exact state, as one checkpoint record.
struct AggregationScalars {
  double L, now, dmax, grid_request;  // grid_request: the widest aggregate a fine cell lists
  std::int64_t alive;
  // planar: 3 - dimension: 1 for disks (2D), 2 for rods (1D); 0 in every 3D checkpoint
  std::int32_t too_large, has_grid, block, planar = 0;
  EngineCounters counters;
};

class AggregationEngine final : public EngineBase {
 public:
  // The grid is rebuilt, wider, once aggregates are this many times fewer
  // than cells (aggregation_engine.cc says how it was chosen): a rebuild
  // costs a search per aggregate, once per this factor of aggregates lost.
  static constexpr double kCellsPerAggregateLimit = 4.0;

  // Aggregates as they are at time `now` (positions valid at now): spheres,
  // disks (z = 0) or rods (y = z = 0).
  AggregationEngine(Particles particles, AggregateState aggregates, double now, const EngineCounters& counters,
                    Geometry g);
  // The engine whose exact state save() wrote.
  explicit AggregationEngine(const StateReader& state);
  // Not copyable: the calendar breaks ties by this engine's own id array.
  AggregationEngine(const AggregationEngine&) = delete;
  AggregationEngine& operator=(const AggregationEngine&) = delete;

  // Counters: `collisions` counts merges (each merge of a chain is one).
  // Throws RunStopped (kAggregateTooLarge) once the largest aggregate is
  // half the box wide.
  RunStatus run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) override;
  double now() const override { return now_; }
  std::size_t size() const override { return m_.size(); }
  double box() const override { return L_; }
  const EngineCounters& counters() const override { return c_; }
  // Kinetic energy per initial particle (Σ ½ m v² / N) and momentum Σ m v,
  // with the number of aggregates and their mean and largest mass.
  Observables observables() const override;
  // Per slot (id order), with id, mass and diameter.
  EngineFrame frame() const override;
  void save(StateWriter& out) const override;

  // For tests: every merge logged; for benchmarks: calendar years started.
  void record_collisions(std::vector<CollisionRecord>* log) { log_ = log; }
  std::int64_t calendar_years() const { return calendar_.years(); }

  std::size_t aggregates() const { return alive_; }
  Geometry geometry() const { return geo_; }
  double largest_diameter() const { return dmax_; }
  double cell_width() const { return grid_ ? grid_->width() : 0.0; }
  std::size_t large_aggregates() const { return large_.size(); }

 private:
  bool present(int i) const { return id_[i] >= 0; }
  void advance(int i);
  bool rebuild_grid(int* follow = nullptr);
  int order_in_space(int follow = -1);
  void place(int i, int fine);
  int fine_cell(int i) const { return large_.contains(i) ? large_.fine_cell(i) : grid_->cell(i); }
  int reach_of(int i) const;
  int size_class(int i) const;
  // Calls f(cell coordinates, shift) for the cells within `reach` of aggregate i's.
  template <class F>
  void for_each_cell_in_reach(int i, int reach, F&& f) const;
  template <class F>
  [[gnu::noinline]] void for_each_cell_in_reach_2d(const CellCoord& c, int reach, F& f) const;
  template <class F>
  [[gnu::noinline]] void for_each_cell_in_reach_1d(const CellCoord& c, int reach, F& f) const;
  [[noreturn]] void throw_too_large() const;
  void check_aggregates(const StateReader& in, std::int64_t alive) const;
  void check_listed(const StateReader& in, const std::vector<std::int32_t>& fine) const;
  bool grid_outdated() const;
  void predict_all();
  struct Search {
    Event event;
    int overlap;
  };
  template <bool kOverlaps>
  Search search(int i) const;
  Event find_event(int i) const;
  template <class F>
  void for_each_candidate(int i, F&& f) const;
  template <class F>
  void for_each_large_image(int i, F&& f) const;
  void cross(int i, int face);
  void merge_chain(int i, int j);
  int merge(int a, int b);
  Vec3 separation(int a, int b) const;  // r_b - r_a at now_, minimum image

  double L_;
  Geometry geo_{3};  // disks: one layer of cells, areas add in a merge; rods: one row, lengths add
  std::vector<Motion> m_;
  std::vector<Image> image_;
  std::vector<double> mass_, diam_;
  std::vector<std::int32_t> id_;
  std::size_t alive_ = 0;
  double dmax_ = 0;
  bool too_large_ = false;  // the largest aggregate is half the box wide: run_until() throws
  double grid_request_ = 0;  // the minimum cell width the grid was built for
  LargeAggregateIndex large_;  // present aggregates wider than grid_request_ (not in grid_'s lists)
  std::unique_ptr<CellGrid> grid_;
  EventCalendar calendar_;  // each aggregate's event (a merge with partner() or a cell crossing)
  double now_;
  EngineCounters c_;
  std::vector<CollisionRecord>* log_ = nullptr;
};

}  // namespace coolgas
