#include "simulate/engine/engine.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "common/compensated_sum.h"
#include "simulate/engine/pair_prediction.h"
#include "simulate/engine/spatial_order.h"
#include "simulate/engine/state_checks.h"

namespace coolgas {

namespace {
// Offsets -1..1 along each axis of D: all 27 cells around (9 in 2D, whose
// one layer has z offset 0; 3 in 1D, whose one row has y offset 0 too).
template <int D>
constexpr int kAroundLo[3] = {-1, -int(Geometry(D).spans(1)), -int(Geometry(D).spans(2))};
template <int D>
constexpr int kAroundHi[3] = {1, int(Geometry(D).spans(1)), int(Geometry(D).spans(2))};
// Inelastic collapse shows as one particle colliding again and again while
// simulated time stops advancing: rule.collapse_limit() collisions in a row,
// each less than kStallGap (relative to 1 + t) after the particle's previous
// event.
constexpr double kStallGap = 1e-11;
// The same, for the whole gas: a window of this many events (or more) over
// which simulated time advanced by at most kStallGap (1 + t). Per-particle
// counts miss a collapse whose collisions are spread over a cluster, or
// reset by rebuilds (every 100 N collisions) before they reach the limit;
// this needs neither N nor r0. A healthy gas of N particles spends 2^20
// events in ~2^20 / N collision times (>= 5e-4 of one for N < 2^31).
constexpr std::int64_t kTimeWatchEvents = std::int64_t(1) << 20;
// Rebuilds are due every this many collisions per particle (see engine.h):
// they renew the Morton order, whose locality decays as particles wander,
// and cost about one partner search per particle. Every 200 keeps long runs
// sorted for a small fraction of the rate that frequent rebuilds cost
// (tests/bench/history.md, "Constants chosen by measurement").
constexpr std::int64_t kCollisionsPerParticlePerRebuild = 200;

// Cells one diameter wide, except in a dilute gas, where they would be more
// than kDiluteCellsPerParticle per particle (phi < 0.033): at phi = 0.005
// they are L^3 = pi N / (6 phi), 105 per particle (3.3 GB of cell heads for
// N = 8e6), and a particle crosses ~20 of them per free flight, each crossing
// an event. There the cells are one mean spacing wide (one particle per cell
// on average, as in the aggregation engine), which was the fastest width
// tried (tests/bench/history.md, "Constants chosen by measurement"). Denser
// gases keep one-diameter cells, and with them their runs bit for bit.
// In 2D the same rule, with the box's area: disks below phi = 0.049.
constexpr double kDiluteCellsPerParticle = 16;

// Rods (D = 1) get cells one mean spacing L/N wide at every density: a free
// flight there is (1 - phi)/phi diameters long (several at phi = 0.2, where
// a sphere's is under one), so one-diameter cells would make each flight
// cross several cells, each crossing an event; with one rod per cell on
// average a flight crosses about one, and a search still meets ~3 rods.
//
// A mixture's cells are as wide as its largest particle (`diameter`), so a
// contact is always between neighbouring cells; the dilute rule counts the
// cells of that width per particle.
template <int D>
double cell_width(double L, std::size_t n, double diameter = 1.0) {
  if constexpr (D == 1) {
    const double most = L / 3.0 / (1.0 + 1e-6);  // three cells, with CellGrid's margin
    return std::max(diameter, std::min(L / double(std::max<std::size_t>(n, 1)), most));
  }
  constexpr Geometry g(D);
  const double volume = g.box_measure(L), particles = double(std::max<std::size_t>(n, 1));
  if (volume <= kDiluteCellsPerParticle * particles * g.power(diameter)) return diameter;
  const double most = L / 3.0 / (1.0 + 1e-6);  // three cells per side, with CellGrid's margin
  const double spacing = g.root(volume / particles);
  return std::max(diameter, std::min(spacing, most));
}

// The width of the rule's largest particle: 1 for equal unit spheres.
template <class Rule>
double largest_diameter(const Rule& rule) {
  if constexpr (Rule::kMixture) return rule.largest_diameter();
  return 1.0;
}

std::int64_t collisions_between_rebuilds(std::size_t n) {
  const auto half = std::int64_t(std::max<std::size_t>(n, 2) / 2);  // two particles per collision
  return kCollisionsPerParticlePerRebuild > std::numeric_limits<std::int64_t>::max() / half
             ? std::numeric_limits<std::int64_t>::max() / 2
             : kCollisionsPerParticlePerRebuild * half;
}
}  // namespace

template <class Rule, int D>
Engine<Rule, D>::Engine(Particles particles, const Rule& rule, double now, const EngineCounters& counters)
    : L_(particles.L),
      rule_(rule),
      grid_(particles.L, cell_width<D>(particles.L, particles.size(), largest_diameter(rule)), particles.size(),
            Geometry(D)),
      now_(now),
      c_(counters) {
  const std::size_t n = particles.size();
  m_.resize(n);
  for (std::size_t i = 0; i < n; ++i) m_[i] = {particles.r[i], particles.v[i], particles.t[i], 0, -1};
  grid_.bind_next_links(&m_[0].next, sizeof(Motion) / sizeof(std::int32_t));
  image_ = std::move(particles.image);
  if constexpr (Rule::kRough) {  // spins not given: at rest
    omega_ = std::move(particles.omega);
    if (omega_.empty()) omega_.resize(n);
    if (omega_.size() != n) throw std::logic_error("a rough engine's particles: one spin per particle");
  }
  if constexpr (Rule::kMixture) {
    species_ = std::move(particles.species);
    if (species_.size() != n) throw std::logic_error("a mixture engine's particles: one species per particle");
    for (const std::uint8_t k : species_)
      if (k >= rule_.species()) throw std::logic_error("a mixture engine's particles: a species beyond the rule's");
  }
  particles = Particles();  // the records hold it all now: free the copy before growing more arrays
  id_.resize(n);
  for (std::size_t i = 0; i < n; ++i) id_[i] = std::int32_t(i);
  calendar_.resize(n);
  later_.resize(n);
  if constexpr (Rule::kDissipative) stall_.assign(n, 0);
  move_all_to_now();
  rebuild();
  watch_ = {c_.events, now_};
}

template <class Rule, int D>
Engine<Rule, D>::Engine(const Rule& rule, const StateReader& in) : rule_(rule) {
  const auto s = in.get_value<EngineScalars>("engine/scalars");
  L_ = s.L;
  now_ = s.now;
  next_rebuild_ = s.next_rebuild;
  c_ = s.counters;
  check_scalars(in, "engine/", L_, now_, c_);
  m_ = in.get<Motion>("engine/motion");
  image_ = in.get<Image>("engine/image");
  id_ = in.get<std::int32_t>("engine/id");
  later_ = in.get<Event>("engine/later");
  stall_ = in.get<std::uint32_t>("engine/stall");
  if constexpr (Rule::kRough) omega_ = in.get<Vec3>("engine/omega");
  if constexpr (Rule::kMixture) species_ = in.get<std::uint8_t>("engine/species");
  const std::size_t n = m_.size();
  if (n == 0 || image_.size() != n || id_.size() != n || later_.size() != n ||
      stall_.size() != (Rule::kDissipative ? n : 0) || omega_.size() != (Rule::kRough ? n : 0) ||
      species_.size() != (Rule::kMixture ? n : 0))
    in.fail("the engine's arrays differ in length");
  check_records(in);
  const double width = cell_width<D>(L_, n, largest_diameter(rule_));
  check_grid_size(in, "engine/grid/heads", CellGrid::cells_for(L_, width, Geometry(D)));
  grid_ = CellGrid(L_, width, n, Geometry(D));
  grid_.bind_next_links(&m_[0].next, sizeof(Motion) / sizeof(std::int32_t));
  grid_.load(in, "engine/grid/");
  for (std::size_t i = 0; i < n; ++i) {
    if (grid_.cell(int(i)) < 0) in.fail("engine/grid/cell[" + std::to_string(i) + "] = -1: every particle has a cell");
    check_in_cell(in, "engine/", i, m_[i].r, grid_, grid_.cell(int(i)));
  }
  calendar_.load(in, "engine/calendar/");
  if (calendar_.size() != n) in.fail("engine/calendar/entries: not one per particle");
  if (!calendar_.queued_from(now_)) in.fail("engine/calendar/entries: an event before now = " + std::to_string(now_));
  if (in.has("engine/time_watch")) {  // absent in checkpoints written before it (format 1 adds only)
    const auto w = in.get_value<TimeWatch>("engine/time_watch");
    if (!(w.events >= 0 && w.events <= c_.events && std::isfinite(w.time) && w.time <= now_))
      in.fail("engine/time_watch: its mark is not a past event and time");
    watch_ = w;
  } else {
    watch_ = {c_.events, now_};
  }
}

// The per-particle arrays of a checkpoint: finite records, ids a
// permutation, kept events well formed (the lists and the calendar check
// themselves as they load).
template <class Rule, int D>
void Engine<Rule, D>::check_records(const StateReader& in) const {
  const std::size_t n = m_.size();
  std::vector<bool> seen(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    check_motion(in, "engine/", i, m_[i], now_, L_);
    const std::int32_t id = id_[i];
    if (id < 0 || std::size_t(id) >= n || seen[std::size_t(id)])
      in.fail("engine/id[" + std::to_string(i) + "] = " + std::to_string(id) + ": ids must be 0.." +
              std::to_string(n - 1) + ", each once");
    seen[std::size_t(id)] = true;
    if (Rule::kRough && !finite(omega_[i])) in.fail("engine/omega[" + std::to_string(i) + "]: not finite");
    if constexpr (Rule::kMixture)
      if (species_[i] >= rule_.species())
        in.fail("engine/species[" + std::to_string(i) + "] = " + std::to_string(species_[i]) + ": the scene has " +
                std::to_string(rule_.species()) + " species");
    if (!EventCalendar::event_in_range(later_[i], std::int64_t(n)))
      in.fail("engine/later[" + std::to_string(i) + "]: an event with a partner or face out of range");
  }
}

template <class Rule, int D>
void Engine<Rule, D>::save(StateWriter& out) const {
  out.put_value("engine/scalars", EngineScalars{L_, now_, next_rebuild_, c_});
  out.put("engine/motion", m_);
  out.put("engine/image", image_);
  out.put("engine/id", id_);
  out.put("engine/later", later_);
  out.put("engine/stall", stall_);
  if constexpr (Rule::kRough) out.put("engine/omega", omega_);
  if constexpr (Rule::kMixture) out.put("engine/species", species_);
  grid_.save(out, "engine/grid/");
  calendar_.save(out, "engine/calendar/");
  out.put_value("engine/time_watch", watch_);
}

// A kick: the state a rebuild starts from (every particle at now_, in id
// order), the velocities changed, then everything rebuilt from them, as
// at construction. The hot loop of run_until is not touched.
template <class Rule, int D>
void Engine<Rule, D>::add_velocities(const std::vector<Vec3>& dv) {
  if (dv.size() != m_.size()) throw std::logic_error("add_velocities: one increment per particle");
  move_all_to_now();
  for (std::size_t i = 0; i < m_.size(); ++i)
    for (int d = 0; d < D; ++d) m_[i].v[d] += dv[i][d];  // the axes beyond D stay exactly 0
  rebuild();
}

// slot_of_id()[id] = the internal index of particle id.
template <class Rule, int D>
std::vector<std::int32_t> Engine<Rule, D>::slot_of_id() const {
  std::vector<std::int32_t> slot(m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i) slot[static_cast<std::size_t>(id_[i])] = std::int32_t(i);
  return slot;
}

template <class Rule, int D>
double Engine<Rule, D>::radius_of(int i) const {
  if constexpr (Rule::kMixture) return rule_.radius[species_[std::size_t(i)]];
  return 0.5;
}

template <class Rule, int D>
double Engine<Rule, D>::mass_of(int i) const {
  if constexpr (Rule::kMixture) return rule_.mass[species_[std::size_t(i)]];
  return 1.0;
}

// Unit masses are not multiplied in: the sums are those of the plain formula, bit for bit.
template <class Rule, int D>
Observables Engine<Rule, D>::observables() const {
  CompensatedSum energy, p[3];
  for (const std::int32_t i : slot_of_id()) {
    const Vec3& v = m_[std::size_t(i)].v;
    if constexpr (Rule::kMixture) {
      const double m = mass_of(i);
      energy.add(0.5 * m * dot(v, v));
      for (int d = 0; d < 3; ++d) p[d].add(m * v[d]);
    } else {
      energy.add(0.5 * dot(v, v));
      for (int d = 0; d < 3; ++d) p[d].add(v[d]);
    }
  }
  Observables o(now_, c_);
  o.kinetic_energy = energy.value() / double(m_.size());
  o.momentum = {p[0].value(), p[1].value(), p[2].value()};
  if constexpr (Rule::kRough) o.rotational_energy = rotational_energy();
  if constexpr (Rule::kMixture) o.species_energy = species_energy();
  return o;
}

// Σ ½ m v² / N_s over the particles of each species, in id order with
// compensation (0 for a species without particles).
template <class Rule, int D>
std::vector<double> Engine<Rule, D>::species_energy() const {
  std::vector<double> out;
  if constexpr (Rule::kMixture) {
    std::vector<CompensatedSum> energy(std::size_t(rule_.species()));
    std::vector<std::int64_t> count(energy.size(), 0);
    for (const std::int32_t i : slot_of_id()) {
      const std::size_t k = species_[std::size_t(i)];
      energy[k].add(0.5 * mass_of(i) * dot(m_[std::size_t(i)].v, m_[std::size_t(i)].v));
      ++count[k];
    }
    out.assign(energy.size(), 0.0);
    for (std::size_t k = 0; k < out.size(); ++k)
      if (count[k] > 0) out[k] = energy[k].value() / double(count[k]);
  }
  return out;
}

// Σ ½ I ω² / N in id order with compensation, I = q a² = q/4 (unit
// diameter and mass).
template <class Rule, int D>
double Engine<Rule, D>::rotational_energy() const {
  if constexpr (Rule::kRough) {
    CompensatedSum energy;
    for (const std::int32_t i : slot_of_id()) energy.add(0.5 * dot(omega_[std::size_t(i)], omega_[std::size_t(i)]));
    return 0.25 * rule_.inertia * energy.value() / double(m_.size());
  }
  return 0;
}

template <class Rule, int D>
EngineFrame Engine<Rule, D>::frame() const {
  EngineFrame f(now_, c_);
  const std::size_t n = m_.size();
  f.position.resize(n);
  f.velocity.resize(n);
  f.image.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto id = static_cast<std::size_t>(id_[i]);
    f.position[id] = position_at(m_[i], now_);
    f.image[id] = image_[i];
    wrap_into_box(f.position[id], f.image[id], L_);
    f.velocity[id] = m_[i].v;
  }
  if constexpr (Rule::kRough) {
    f.angular_velocity.resize(n);
    for (std::size_t i = 0; i < n; ++i) f.angular_velocity[static_cast<std::size_t>(id_[i])] = omega_[i];
  }
  if constexpr (Rule::kMixture) {
    f.species.resize(n);
    for (std::size_t i = 0; i < n; ++i) f.species[static_cast<std::size_t>(id_[i])] = species_[i];
  }
  return f;
}

template <class Rule, int D>
void Engine<Rule, D>::advance(int i) {
  Motion& m = m_[i];
  m.r = position_at(m, now_);
  m.t = now_;
}

// Every particle to now_, wrapped, counts reset, in id order: the state a
// rebuild starts from.
template <class Rule, int D>
void Engine<Rule, D>::move_all_to_now() {
  for (std::size_t i = 0; i < m_.size(); ++i) {
    advance(int(i));
    wrap_into_box(m_[i].r, image_[i], L_);
    m_[i].count = 0;
  }
  order_by_id();
}

template <class Rule, int D>
std::vector<Vec3> Engine<Rule, D>::release_positions() {
  move_all_to_now();
  calendar_ = EventCalendar();
  grid_ = CellGrid();
  image_ = {};
  id_ = {};
  later_ = {};
  stall_ = {};
  omega_ = {};
  species_ = {};
  std::vector<Vec3> r(m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i) r[i] = m_[i].r;
  m_ = {};
  return r;
}

// Renumbers the particles along the Morton curve of their cells (ties by id,
// so the order depends on the positions alone). Key and index share one
// 64-bit word, so the sort holds 8 bytes per particle, not 16: the curve
// runs through blocks of cells when the grid has more than 2^10 per side.
template <class Rule, int D>
void Engine<Rule, D>::order_by_space() {
  int coarse = 0;
  while ((grid_.cells_per_side() - 1) >> coarse >= 1 << 10) ++coarse;
  std::vector<std::uint64_t> keys(m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i) {
    const CellCoord c = grid_.coord(grid_.cell_of(m_[i].r.x, m_[i].r.y, m_[i].r.z));
    const std::uint64_t cell_key =
        morton_key(std::uint32_t(c.x) >> coarse, std::uint32_t(c.y) >> coarse, std::uint32_t(c.z) >> coarse);
    keys[i] = cell_key << 32 | i;  // i is the id: called right after move_all_to_now()
  }
  std::sort(keys.begin(), keys.end());
  std::vector<std::int32_t> order(m_.size());
  for (std::size_t k = 0; k < keys.size(); ++k) order[k] = std::int32_t(keys[k] & 0xffffffffu);
  keys = {};
  apply_permutation(m_, order);
  apply_permutation(image_, order);
  apply_permutation(id_, order);
  if constexpr (Rule::kRough) apply_permutation(omega_, order);
  if constexpr (Rule::kMixture) apply_permutation(species_, order);
}

template <class Rule, int D>
void Engine<Rule, D>::order_by_id() {
  std::vector<std::int32_t> order(m_.size());  // order[id] = where particle id is now
  for (std::size_t i = 0; i < m_.size(); ++i) order[static_cast<std::size_t>(id_[i])] = std::int32_t(i);
  apply_permutation(m_, order);
  apply_permutation(image_, order);
  apply_permutation(id_, order);
  if constexpr (Rule::kRough) apply_permutation(omega_, order);
  if constexpr (Rule::kMixture) apply_permutation(species_, order);
}

// Everything but the particles, rebuilt from the particles (at now_).
template <class Rule, int D>
void Engine<Rule, D>::rebuild() {
  order_by_space();
  grid_.clear();
  for (std::size_t i = 0; i < m_.size(); ++i) grid_.insert(int(i), grid_.cell_of(m_[i].r.x, m_[i].r.y, m_[i].r.z));
  std::fill(stall_.begin(), stall_.end(), 0u);
  for (std::size_t i = 0; i < m_.size(); ++i) calendar_.assign(int(i), find_event(int(i)));
  calendar_.reset(now_);
  next_rebuild_ = c_.collisions + collisions_between_rebuilds(m_.size());
}

// The periodic shift that brings a particle of cell `to` next to one in cell
// `from` (the cells are neighbours, so each coordinate differs by -1, 0 or 1
// modulo the grid).
template <class Rule, int D>
Vec3 Engine<Rule, D>::image_shift(int from, int to) const {
  const CellCoord a = grid_.coord(from), b = grid_.coord(to);
  auto shift = [&](int ca, int cb) { return cb - ca > 1 ? -L_ : (ca - cb > 1 ? L_ : 0.0); };
  return {shift(a.x, b.x), shift(a.y, b.y), shift(a.z, b.z)};
}

template <class Rule, int D>
void Engine<Rule, D>::scan_list(const Vec3& ri, const Vec3& vi, double ai, int first, const double* s,
                                double& best, int& code) const {
  double b = best;  // locals, not the references, so they can stay in registers
  int c = code;
  [[maybe_unused]] const double* radius = nullptr;
  if constexpr (Rule::kMixture) radius = rule_.radius.data();
  for (int j = first; j >= 0; j = m_[j].next) {
    const Motion& mj = m_[j];
    const double dtj = now_ - mj.t;
    const Vec3 dr{mj.r.x + mj.v.x * dtj + s[0] - ri.x, mj.r.y + mj.v.y * dtj + s[1] - ri.y,
                  mj.r.z + mj.v.z * dtj + s[2] - ri.z};
    const Vec3 dv{mj.v.x - vi.x, mj.v.y - vi.y, mj.v.z - vi.z};
    double t;
    if constexpr (Rule::kMixture) {
      const double sigma = ai + radius[species_[std::size_t(j)]];
      t = time_to_contact_unbranched(dr, dv, sigma * sigma);  // kNever for j == i
    } else {
      t = time_to_contact_unbranched(dr, dv);  // kNever for j == i
    }
    c = t < b ? j : c;  // selects, not branches (see time_to_contact_unbranched)
    b = std::min(t, b);
  }
  best = b;
  code = c;
}

// The first half of a partner search around cell `home`: the cells
// (offsets lo..hi), the non-empty ones picked out without branching (about
// two in three cells are empty, at random), their list heads read all
// together and the first particle of each prefetched, so that the misses
// overlap instead of following one another (the search is bound by memory
// latency). Two searches started one after the other overlap too.
template <class Rule, int D>
void Engine<Rule, D>::start_search(int home, const int* lo, const int* hi, Search& s) const {
  int slots[27];
  const int count = neighbour_slots<D>(grid_, L_, grid_.coord(home), lo, hi, slots, s.shifts, s.wraps);
  s.n = 0;
  for (int k = 0; k < count; ++k) {
    s.heads[s.n] = grid_.first_in_slot(slots[k]);
    s.which[s.n] = k;
    s.n += s.heads[s.n] >= 0;
  }
  for (int k = 0; k < s.n; ++k) __builtin_prefetch(&m_[s.heads[k]]);
}

// The second half: the earliest contact (at now_, at ri with vi) with the
// particles of the search's cells, if earlier than best (relative to now_);
// updates best and partner.
template <class Rule, int D>
void Engine<Rule, D>::finish_search(const Vec3& ri, const Vec3& vi, double ai, const Search& s, double& best,
                                    int& partner) const {
  static constexpr double kNoShift[3] = {0, 0, 0};
  for (int k = 0; k < s.n; ++k)
    scan_list(ri, vi, ai, s.heads[k], s.wraps ? s.shifts[s.which[k]] : kNoShift, best, partner);
}

// The event of particle i (at now_ at ri with vi) given its earliest
// collision: that collision, or its first cell crossing if that comes first
// (ties go to the crossing); the collision is then kept in later_.
template <class Rule, int D>
Event Engine<Rule, D>::earliest(int i, const Vec3& ri, const Vec3& vi, const Event& collision) {
  const CellExit exit = first_cell_exit(grid_, grid_.cell(i), ri, vi);
  if (collision.time < now_ + exit.time) return collision;
  later_[i] = collision;
  return exit.face >= 0 ? Event::crossing(now_ + exit.time, exit.face) : Event{};
}

// Particle i is at now_; finds its earliest event: the first face of its cell
// it will cross, or an earlier contact with a particle in the 27 cells around.
template <class Rule, int D>
Event Engine<Rule, D>::find_event(int i) {
  Search s;
  start_search(grid_.cell(i), kAroundLo<D>, kAroundHi<D>, s);
  return finish_event(i, s);
}

// find_event() once the search of the 27 cells around i has been started.
template <class Rule, int D>
Event Engine<Rule, D>::finish_event(int i, const Search& s) {
  const Vec3 ri = m_[i].r, vi = m_[i].v;
  double best = kNever;
  int partner = -1;
  finish_search(ri, vi, radius_of(i), s, best, partner);
  if (partner < 0) return earliest(i, ri, vi, Event{});
  return earliest(i, ri, vi, Event::collision(now_ + best, partner, m_[partner].count));
}

// Particle i crosses `face` of its cell into the next one, its velocity
// unchanged; returns its next event. Its kept collision is still the
// earliest with the particles that were its neighbours if that partner has
// not collided since (any other that has collided has searched again itself,
// and found i if due); only the layer of 9 cells (3 in 2D, 1 in 1D) beyond the new cell has to
// be searched. That search is started first, so its loads are in flight
// while the grid is updated and the partner checked.
template <class Rule, int D>
Event Engine<Rule, D>::cross(int i, int face) {
  const Event kept = later_[i];
  if (kept.is_collision()) __builtin_prefetch(&m_[kept.partner()]);
  advance(i);
  const int to = cell_across_face(grid_, grid_.cell(i), face, L_, m_[i].r, image_[i]);
  const int d = face / 2, side = face % 2 == 1 ? 1 : -1;
  int lo[3] = {-1, kAroundLo<D>[1], kAroundLo<D>[2]}, hi[3] = {1, kAroundHi<D>[1], kAroundHi<D>[2]};
  lo[d] = hi[d] = side;
  Search s;
  start_search(to, lo, hi, s);
  grid_.move(i, to);
  if (kept.is_collision() && m_[kept.partner()].count != kept.partner_count) return find_event(i);
  const Vec3 ri = m_[i].r, vi = m_[i].v;
  double best = kept.time - now_;
  int partner = -1;
  finish_search(ri, vi, radius_of(i), s, best, partner);
  if (partner < 0) return earliest(i, ri, vi, kept);
  return earliest(i, ri, vi, Event::collision(now_ + best, partner, m_[partner].count));
}

template <class Rule, int D>
void Engine<Rule, D>::note_collision_gap(int i, double gap, int partner) {
  if constexpr (Rule::kDissipative) {  // elastic spheres cannot collapse
    if (gap > kStallGap * (1.0 + now_)) {
      stall_[i] = 0;
      return;
    }
    if (++stall_[i] < static_cast<unsigned>(rule_.collapse_limit())) return;
    std::ostringstream s;
    s << "inelastic collapse at t = " << now_ << ": particle " << id_[i] << " collided " << rule_.collapse_limit()
      << " times in a row (last with particle " << id_[partner] << ") without simulated time advancing";
    throw RunStopped(StopReason::kInelasticCollapse, s.str(), now_);
  }
}

// Called every 4096 events (pause_due): once a window of kTimeWatchEvents
// has passed, simulated time must have advanced, else the run is stuck in
// inelastic collapse. The window starts where the last one ended, at an
// event count, whatever the slicing of run_until, and is saved with the
// engine: a resumed run stops where the whole one does.
template <class Rule, int D>
void Engine<Rule, D>::watch_time() {
  if constexpr (Rule::kDissipative) {
    const std::int64_t events = c_.events - watch_.events;
    if (events < kTimeWatchEvents) return;
    if (now_ - watch_.time <= kStallGap * (1.0 + now_)) {
      std::ostringstream s;
      s << "inelastic collapse at t = " << now_ << ": " << events << " events (" << c_.collisions
        << " collisions in all) without simulated time advancing (from t = " << watch_.time << ")";
      throw RunStopped(StopReason::kInelasticCollapse, s.str(), now_);
    }
    watch_ = {c_.events, now_};
  }
}

template <class Rule, int D>
void Engine<Rule, D>::collide(int i, int j) {
  note_collision_gap(i, now_ - m_[i].t, j);
  note_collision_gap(j, now_ - m_[j].t, i);
  advance(i);
  advance(j);
  const Vec3 s = image_shift(grid_.cell(i), grid_.cell(j));
  const Vec3& ri = m_[i].r;
  const Vec3& rj = m_[j].r;
  Vec3 n{rj.x + s.x - ri.x, rj.y + s.y - ri.y, rj.z + s.z - ri.z};
  const double inv = 1.0 / std::sqrt(dot(n, n));
  n = {n.x * inv, n.y * inv, n.z * inv};
  Vec3& vi = m_[i].v;
  Vec3& vj = m_[j].v;
  const double g = (vi.x - vj.x) * n.x + (vi.y - vj.y) * n.y + (vi.z - vj.z) * n.z;
  if (g > 0) {  // approaching (always, but for round-off at grazing contact)
    bool below = false;
    double r;
    if constexpr (Rule::kMixture) r = rule_.restitution(g, species_[std::size_t(i)], species_[std::size_t(j)], below);
    else r = rule_.restitution(g, below);
    if constexpr (Rule::kRough)
      apply_tangential_restitution(vi, vj, omega_[i], omega_[j], n, rule_.eta_t, rule_.spin_turn);
    if constexpr (Rule::kMixture)
      apply_restitution_with_masses(vi, vj, n, g, r, mass_of(i), mass_of(j));
    else
      apply_restitution(vi, vj, n, g, r);
    c_.below_delta += below;
  }
  ++m_[i].count;
  ++m_[j].count;
  ++c_.collisions;
  if (log_) log_->push_back({std::min(id_[i], id_[j]), std::max(id_[i], id_[j]), now_});
}

template <class Rule, int D>
RunStatus Engine<Rule, D>::run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) {
  const std::int64_t last_event = c_.events + max_events;
  while (true) {
    if (RunStatus paused; pause_due(c_.events, last_event, interrupt, paused, [this] { watch_time(); }))
      return paused;
    const int i = calendar_.top();
    if (i < 0) break;
    for (int k = 0; k < 2; ++k)
      if (const int next = calendar_.runner_up(k); next >= 0) {
        // Its calendar entry is in cache (it was touched when the bucket was
        // sorted); what the event will read next is not.
        __builtin_prefetch(&m_[next]);
        grid_.prefetch_cell(next);
        const Event& upcoming = calendar_.event(next);
        if (upcoming.is_collision()) {  // its partner's record and calendar entry (to be rescheduled)
          const int partner = upcoming.partner();
          __builtin_prefetch(&m_[partner]);
          grid_.prefetch_cell(partner);
          calendar_.prefetch_event(partner);
          if constexpr (Rule::kRough) {  // the spins the collision turns
            __builtin_prefetch(&omega_[next]);
            __builtin_prefetch(&omega_[partner]);
          }
          if constexpr (Rule::kMixture) {  // the species that give the collision's masses
            __builtin_prefetch(&species_[next]);
            __builtin_prefetch(&species_[partner]);
          }
        } else {  // a crossing: the collision it kept, and its image counts
          __builtin_prefetch(&later_[next]);
          __builtin_prefetch(&image_[next]);
        }
      }
    const Event ev = calendar_.event(i);
    if (ev.time > t_stop) break;
    now_ = ev.time;
    ++c_.events;
    if (ev.is_collision()) {
      const int code = ev.partner();
      if (m_[code].count != ev.partner_count) {  // partner collided since: stale
        ++c_.stale;
        advance(i);
        calendar_.schedule(i, find_event(i));
        continue;
      }
      // Both searches are started before either is finished, and before the
      // collision itself (they read only cells): their misses overlap with
      // each other and with the collision's arithmetic.
      // The partner's calendar neighbours load meanwhile too, and each new
      // event's bucket head while the other event is found.
      calendar_.prefetch_unlink(code);
      Search si, sj;
      start_search(grid_.cell(i), kAroundLo<D>, kAroundHi<D>, si);
      start_search(grid_.cell(code), kAroundLo<D>, kAroundHi<D>, sj);
      collide(i, code);
      const Event ei = finish_event(i, si);
      calendar_.prefetch_insert(ei.time);
      const Event ej = finish_event(code, sj);
      calendar_.prefetch_insert(ej.time);
      calendar_.schedule(i, ei);
      calendar_.schedule(code, ej);
      if (c_.collisions >= next_rebuild_) {  // the engine's own schedule, never the caller's
        move_all_to_now();
        rebuild();
      }
    } else if (ev.kind() == EventKind::kCrossing) {
      calendar_.schedule(i, cross(i, ev.face()));
    } else {
      break;  // nothing left to happen (only with t_stop = +inf)
    }
  }
  now_ = std::max(now_, t_stop);
  return RunStatus::kReached;
}

// Every rule of collision_rules.h in every dimension: a new rule is one line here.
#define COOLGAS_ENGINE_OF(Rule) \
  template class Engine<Rule, 1>; \
  template class Engine<Rule, 2>; \
  template class Engine<Rule, 3>;
COOLGAS_ENGINE_OF(ElasticRule)
COOLGAS_ENGINE_OF(ConstantRestitutionRule)
COOLGAS_ENGINE_OF(ViscoelasticRule)
// Rough spheres and disks (rods cannot spin: the scene refuses them).
template class Engine<RoughRule<ElasticRule>, 2>;
template class Engine<RoughRule<ElasticRule>, 3>;
template class Engine<RoughRule<ConstantRestitutionRule>, 2>;
template class Engine<RoughRule<ConstantRestitutionRule>, 3>;
template class Engine<RoughRule<ViscoelasticRule>, 2>;
template class Engine<RoughRule<ViscoelasticRule>, 3>;
// Mixtures of sizes and masses, of every rule (the scene refuses rough
// mixtures), in every dimension.
COOLGAS_ENGINE_OF(MixtureRule<ElasticRule>)
COOLGAS_ENGINE_OF(MixtureRule<ConstantRestitutionRule>)
COOLGAS_ENGINE_OF(MixtureRule<ViscoelasticRule>)

#undef COOLGAS_ENGINE_OF

}  // namespace coolgas
