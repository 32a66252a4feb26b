#include "simulate/engine/aggregation_engine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/compensated_sum.h"
#include "simulate/engine/aggregation_reach.h"
#include "simulate/engine/pair_prediction.h"
#include "simulate/engine/spatial_order.h"
#include "simulate/engine/state_checks.h"

namespace coolgas {

namespace {
// Fine cells are this many times the mean distance between aggregates when
// the grid is rebuilt (about one aggregate per cell, 27 candidates per
// search); the grid is rebuilt, wider, once aggregates are
// AggregationEngine::kCellsPerAggregateLimit times fewer than cells. The
// large aggregates are indexed in blocks of kBlock³ fine cells. The factor
// and the limit are the fastest of those tried on W3
// (tests/bench/history.md, "Constants chosen by measurement").
constexpr double kSpacingFactor = 1.0;
constexpr int kBlock = 2;
// The grid's and the large index's list links live in the motion records
// (Motion::next), so walking a list reads one cache line per candidate.
constexpr std::size_t kLinkStride = sizeof(Motion) / sizeof(std::int32_t);
}  // namespace

AggregateState AggregateState::unit_spheres(std::size_t n) {
  AggregateState a;
  a.mass.assign(n, 1.0);
  a.diameter.assign(n, 1.0);
  a.id.resize(n);
  for (std::size_t i = 0; i < n; ++i) a.id[i] = std::int32_t(i);
  return a;
}

AggregateState AggregateState::of_species(const std::vector<std::uint8_t>& species, const std::vector<double>& mass,
                                          const std::vector<double>& diameter) {
  AggregateState a = unit_spheres(species.size());
  for (std::size_t i = 0; i < species.size(); ++i) {
    a.mass[i] = mass.at(species[i]);
    a.diameter[i] = diameter.at(species[i]);
  }
  return a;
}

AggregationEngine::AggregationEngine(Particles particles, AggregateState a, double now, const EngineCounters& counters,
                                     Geometry g)
    : L_(particles.L), geo_(g), now_(now), c_(counters) {
  const std::size_t n = particles.size();
  m_.resize(n);
  for (std::size_t i = 0; i < n; ++i) m_[i] = {particles.r[i], particles.v[i], particles.t[i], 0, -1};
  image_ = std::move(particles.image);
  particles = Particles{};  // before the grid is built: the peak memory
  mass_ = std::move(a.mass);
  diam_ = std::move(a.diameter);
  id_ = std::move(a.id);
  for (std::size_t i = 0; i < n; ++i) {
    if (!present(int(i))) continue;
    ++alive_;
    dmax_ = std::max(dmax_, diam_[i]);
  }
  calendar_.break_ties_by(id_.data());  // id_ is permuted in place: its data stay put
  // The state alone decides the grid, so a run resumed from a dump builds
  // the same grid as one started from the same state.
  if (rebuild_grid()) predict_all();
}

AggregationEngine::AggregationEngine(const StateReader& in) {
  const auto s = in.get_value<AggregationScalars>("aggregation/scalars");
  L_ = s.L;
  now_ = s.now;
  dmax_ = s.dmax;
  grid_request_ = s.grid_request;
  alive_ = std::size_t(s.alive);
  too_large_ = s.too_large != 0;
  c_ = s.counters;
  check_scalars(in, "aggregation/", L_, now_, c_);
  if ((s.too_large != 0 && s.too_large != 1) || (s.has_grid != 0 && s.has_grid != 1) ||
      (s.planar < 0 || s.planar > 2) || (s.block != 1 && s.block != kBlock))
    in.fail("aggregation/scalars: flags " + std::to_string(s.too_large) + ", " + std::to_string(s.has_grid) + ", " +
            std::to_string(s.planar) + " and block " + std::to_string(s.block) + "; must be 0 or 1 (planar: 0 to 2), and 1 or " +
            std::to_string(kBlock));
  geo_ = Geometry(3 - int(s.planar));
  m_ = in.get<Motion>("aggregation/motion");
  image_ = in.get<Image>("aggregation/image");
  mass_ = in.get<double>("aggregation/mass");
  diam_ = in.get<double>("aggregation/diameter");
  id_ = in.get<std::int32_t>("aggregation/id");
  const std::size_t n = m_.size();
  if (n == 0 || image_.size() != n || mass_.size() != n || diam_.size() != n || id_.size() != n)
    in.fail("the aggregation engine's arrays differ in length");
  check_aggregates(in, s.alive);
  calendar_.break_ties_by(id_.data());  // before the calendar loads: its heap order is checked by ids
  if (s.has_grid) {
    if (!(std::isfinite(grid_request_) && grid_request_ > 0 && grid_request_ <= L_))
      in.fail("aggregation/scalars: cell width " + std::to_string(grid_request_) + " out of (0, L]");
    check_grid_size(in, "aggregation/grid/heads", CellGrid::cells_for(L_, grid_request_, geo_));
    grid_ = std::make_unique<CellGrid>(L_, grid_request_, n, geo_);
    if (grid_->cells_per_side() % s.block != 0) in.fail("aggregation/scalars: the block does not divide the grid");
    grid_->bind_next_links(&m_[0].next, kLinkStride);
    grid_->load(in, "aggregation/grid/");
    large_ = LargeAggregateIndex(grid_->cells_per_side(), s.block, n, geo_);
    large_.bind_links(&m_[0].next, kLinkStride);
    const auto fine = in.get<std::int32_t>("aggregation/large_cell");
    if (fine.size() != n) in.fail("the aggregation engine's arrays differ in length");
    check_listed(in, fine);
    large_.assign(fine, [this](int i) { return size_class(i); });
  }
  calendar_.load(in, "aggregation/calendar/");
  if (calendar_.size() != n) in.fail("aggregation/calendar/entries: not one per slot");
  if (!calendar_.queued_from(now_))
    in.fail("aggregation/calendar/entries: an event before now = " + std::to_string(now_));
}

// The per-slot arrays of a checkpoint: present aggregates with finite
// records, ids distinct in 0..n-1, mass and diameter finite and positive
// (diameter at most L), their count and largest diameter those stored;
// empty slots with id -1.
void AggregationEngine::check_aggregates(const StateReader& in, std::int64_t alive) const {
  const std::size_t n = m_.size();
  std::vector<bool> seen(n, false);
  std::int64_t present_count = 0;
  double widest = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::int32_t id = id_[i];
    if (id == -1) continue;
    if (id < 0 || std::size_t(id) >= n || seen[std::size_t(id)])
      in.fail("aggregation/id[" + std::to_string(i) + "] = " + std::to_string(id) + ": ids must be 0.." +
              std::to_string(n - 1) + ", each once, or -1 (an empty slot)");
    seen[std::size_t(id)] = true;
    check_motion(in, "aggregation/", i, m_[i], now_, L_);
    if (!(std::isfinite(mass_[i]) && mass_[i] > 0 && std::isfinite(diam_[i]) && diam_[i] > 0 && diam_[i] <= L_))
      in.fail("aggregation/slot " + std::to_string(i) + ": mass " + std::to_string(mass_[i]) + ", diameter " +
              std::to_string(diam_[i]) + "; must be > 0, the diameter at most L");
    ++present_count;
    widest = std::max(widest, diam_[i]);
  }
  if (present_count != alive || widest != dmax_)
    in.fail("aggregation/scalars: " + std::to_string(alive) + " aggregates, the largest " + std::to_string(dmax_) +
            " wide, but the slots hold " + std::to_string(present_count) + ", the largest " + std::to_string(widest));
}

// Where each slot is listed: a present aggregate no wider than a fine cell
// in the grid (and in its cell), a wider one in the large index (fine cell
// `fine[i]`, in range), an empty slot nowhere.
void AggregationEngine::check_listed(const StateReader& in, const std::vector<std::int32_t>& fine) const {
  for (std::size_t i = 0; i < m_.size(); ++i) {
    const bool in_grid = grid_->cell(int(i)) >= 0, large = fine[i] >= 0;
    const bool want_grid = present(int(i)) && diam_[i] <= grid_request_;
    const bool want_large = present(int(i)) && !want_grid;
    if (in_grid != want_grid || large != want_large || fine[i] < -1 || fine[i] >= grid_->cell_count())
      in.fail("aggregation/slot " + std::to_string(i) + " is listed where it does not belong (grid cell " +
              std::to_string(grid_->cell(int(i))) + ", large-index cell " + std::to_string(fine[i]) + ")");
    if (present(int(i))) check_in_cell(in, "aggregation/", i, m_[i].r, *grid_, in_grid ? grid_->cell(int(i)) : fine[i]);
  }
}

void AggregationEngine::save(StateWriter& out) const {
  out.put_value("aggregation/scalars", AggregationScalars{L_, now_, dmax_, grid_request_, std::int64_t(alive_),
                                                          too_large_, grid_ != nullptr, large_.block(), 3 - geo_.d(), c_});
  out.put("aggregation/motion", m_);
  out.put("aggregation/image", image_);
  out.put("aggregation/mass", mass_);
  out.put("aggregation/diameter", diam_);
  out.put("aggregation/id", id_);
  if (grid_) {
    grid_->save(out, "aggregation/grid/");
    out.put("aggregation/large_cell", large_.fine_cells());
  }
  calendar_.save(out, "aggregation/calendar/");
}

EngineFrame AggregationEngine::frame() const {
  EngineFrame f(now_, c_);
  const std::size_t n = m_.size();
  f.position.assign(n, Vec3{});  // an absent id: all zero, id -1
  f.velocity.assign(n, Vec3{});
  f.image.assign(n, Image{0, 0, 0});
  f.id.assign(n, -1);
  f.mass.assign(n, 0.0);
  f.diameter.assign(n, 0.0);
  for (std::size_t s = 0; s < n; ++s) {
    if (!present(int(s))) continue;
    const auto k = std::size_t(id_[s]);
    f.id[k] = id_[s];
    f.velocity[k] = m_[s].v;
    f.image[k] = image_[s];
    f.position[k] = position_at(m_[s], now_);
    wrap_into_box(f.position[k], f.image[k], L_);
    f.mass[k] = mass_[s];
    f.diameter[k] = diam_[s];
  }
  return f;
}

void AggregationEngine::advance(int i) {
  Motion& m = m_[i];
  m.r = position_at(m, now_);
  m.t = now_;
}

// A grid of three cells per side cannot be coarser.
bool AggregationEngine::grid_outdated() const {
  return grid_->cells_per_side() > 3 && double(grid_->cell_count()) > kCellsPerAggregateLimit * double(alive_);
}

// Aggregate i (present, at now_, wrapped) listed in fine cell `fine`: in the
// grid's lists if no wider than a cell, else in the large index.
void AggregationEngine::place(int i, int fine) {
  if (diam_[i] <= grid_request_) {
    grid_->insert(i, fine);
  } else {
    large_.insert(i, fine, size_class(i));
  }
}

// How many cells out aggregate i's search looks: 1 for one no wider than a
// cell, else far enough for any partner no wider than a cell (wider ones
// are found through the large index).
int AggregationEngine::reach_of(int i) const {
  return diam_[i] <= grid_request_ ? 1 : cell_reach(0.5 * (diam_[i] + grid_request_), grid_request_);
}

// A large aggregate's class in the index: its reach, less 2 (the least).
int AggregationEngine::size_class(int i) const { return reach_of(i) - 2; }

// Every aggregate to now_, wrapped, into a new grid, its slots first put in
// the order of its cells (order_in_space; *follow becomes the new slot of
// slot *follow): fine cells about
// kSpacingFactor mean distances wide (at most L/3: three cells per side),
// a whole number of index blocks per side. Returns false
// (aggregates moved and wrapped, no grid) when the largest aggregate is half
// the box wide; run_until() then reports it.
bool AggregationEngine::rebuild_grid(int* follow) {
  for (std::size_t i = 0; i < m_.size(); ++i) {
    if (!present(int(i))) continue;
    advance(int(i));
    wrap_into_box(m_[i].r, image_[i], L_);
  }
  too_large_ = 2.0 * dmax_ >= L_;
  if (too_large_) return false;
  const double per_aggregate =
      geo_.box_measure(L_) / double(std::max<std::size_t>(alive_, 1));
  const double spacing =
      geo_.root(per_aggregate);
  const double widest = L_ / 3.0 / (1.0 + 1e-6);  // three cells per side, with CellGrid's own margin
  const double wanted = std::min(spacing * kSpacingFactor, widest);
  const int fine = int(std::floor(L_ / (wanted * (1.0 + 1e-6))));
  const int block = fine >= 3 * kBlock ? kBlock : 1;
  const int n = fine / block * block;  // whole blocks
  grid_ = std::make_unique<CellGrid>(L_, L_ / (n + 0.5), m_.size(), geo_);  // exactly n cells per side
  const int moved = order_in_space(follow ? *follow : -1);
  if (follow) *follow = moved;
  grid_->bind_next_links(&m_[0].next, kLinkStride);
  grid_request_ = grid_->width() / (1.0 + 1e-6);
  large_ = LargeAggregateIndex(n, block, m_.size(), geo_);
  large_.bind_links(&m_[0].next, kLinkStride);  // a large aggregate is in no fine list
  for (std::size_t i = 0; i < m_.size(); ++i)
    if (present(int(i))) place(int(i), grid_->cell_of(m_[i].r.x, m_[i].r.y, m_[i].r.z));
  return true;
}

// The slots reordered along a Morton curve through the new grid's cells, the
// empty ones last, so that aggregates close in space are close in memory and
// a search's candidates mostly hit cache instead of main memory (W3 at
// N = 1e6: tests/bench/README.md). Ids never change: slot s holds aggregate
// id_[s]. Called before anything is listed in the grid, the index or the
// calendar, which are all built afresh after it. Returns the new slot of
// slot `follow`.
int AggregationEngine::order_in_space(int follow) {
  const std::size_t n = m_.size();
  int shift = 0;  // keys of 30 bits: 1024 cells per side at most
  while ((grid_->cells_per_side() - 1) >> shift >= 1024) ++shift;
  std::vector<std::uint64_t> key;  // the Morton key of its cell << 32 | slot, for each present slot
  key.reserve(alive_);
  for (std::size_t i = 0; i < n; ++i) {
    if (!present(int(i))) continue;
    const CellCoord c = grid_->coord(grid_->cell_of(m_[i].r.x, m_[i].r.y, m_[i].r.z));
    key.push_back(morton_key(std::uint32_t(c.x >> shift), std::uint32_t(c.y >> shift), std::uint32_t(c.z >> shift))
                      << 32 |
                  std::uint64_t(i));
  }
  std::sort(key.begin(), key.end());
  std::vector<std::int32_t> order(n);  // order[k]: the slot that becomes slot k
  for (std::size_t k = 0; k < key.size(); ++k) order[k] = std::int32_t(key[k] & 0xffffffffu);
  std::size_t k = key.size();
  key = {};
  for (std::size_t i = 0; i < n; ++i)
    if (!present(int(i))) order[k++] = std::int32_t(i);
  int moved = follow;
  for (std::size_t j = 0; j < n; ++j)
    if (order[j] == follow) moved = int(j);
  apply_permutation(m_, order);
  apply_permutation(image_, order);
  apply_permutation(mass_, order);
  apply_permutation(diam_, order);
  apply_permutation(id_, order);
  return moved;
}

void AggregationEngine::throw_too_large() const {
  std::ostringstream s;
  s << "aggregation at t = " << now_ << ": the largest aggregate (diameter " << dmax_
    << ") is half the box wide or more (L = " << L_
    << "), where an aggregate could touch another through two periodic images, with " << alive_
    << " aggregates left; use a larger system (more particles) to go on";
  throw RunStopped(StopReason::kAggregateTooLarge, s.str(), now_);
}

void AggregationEngine::predict_all() {
  calendar_.resize(m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i)
    if (present(int(i))) calendar_.assign(int(i), find_event(int(i)));
  calendar_.reset(now_);
}

template <class F>
void AggregationEngine::for_each_cell_in_reach(int i, int reach, F&& f) const {
  const CellCoord c = grid_->coord(fine_cell(i));
  // Expected 3D: the hint keeps the 3D walk's code as short as before rods
  // (a plain geo_.d() != 3 test reordered its blocks and grew it).
  if (__builtin_expect(geo_.d() != 3, 0)) return for_each_cell_in_reach_2d(c, reach, f);
  if (reach == 1) {
    for_each_neighbour_cell(grid_->cells_per_side(), L_, c, [&](const NeighbourCell& nb) { f(nb.cell, nb.shift); });
  } else {
    for_each_cell_within(grid_->cells_per_side(), L_, c, reach, reach, f);
  }
}

// The same on the one layer of a 2D grid (or the one row of a 1D one); out of
// line, so that the 3D walk above compiles as it did before disks (W3:
// tests/bench/README.md).
template <class F>
void AggregationEngine::for_each_cell_in_reach_2d(const CellCoord& c, int reach, F& f) const {
  static constexpr int kLo[3] = {-1, -1, 0}, kHi[3] = {1, 1, 0};
  if (geo_.d() == 1) return for_each_cell_in_reach_1d(c, reach, f);
  if (reach == 1) {
    for_each_neighbour_cell(grid_->cells_per_side(), L_, c, kLo, kHi,
                            [&](const NeighbourCell& nb) { f(nb.cell, nb.shift); });
  } else {
    for_each_cell_within(grid_->cells_per_side(), L_, c, reach, 0, f);
  }
}

// The cells within reach along the one row of a 1D ring.
template <class F>
void AggregationEngine::for_each_cell_in_reach_1d(const CellCoord& c, int reach, F& f) const {
  for (int o = -reach; o <= reach; ++o) {
    const AxisStep x = axis_step(c.x, o, grid_->cells_per_side(), L_);
    f(CellCoord{x.cell, 0, 0}, Vec3{x.shift, 0.0, 0.0});
  }
}

// Calls f(j, shift) for every large aggregate j (not i) at every periodic
// image its pair's reach allows. On a 1D ring the y offsets are those of one
// row: a reach of a whole grid side adds the images at y = ±L, which no
// contact (< L/2) can reach; left in, so that the 3D search is as before.
template <class F>
void AggregationEngine::for_each_large_image(int i, F&& f) const {
  const int n = grid_->cells_per_side();
  const int fine = fine_cell(i);
  const CellCoord ci = grid_->coord(fine);
  const double di = diam_[i], w = grid_request_;
  auto images = [&](int j) {
    if (j == i) return;
    const int reach = cell_reach(0.5 * (di + diam_[j]), w);
    const CellCoord cj = grid_->coord(large_.fine_cell(j));
    for_each_image_offset(cj.z - ci.z, n, L_, geo_.spans(2) ? reach : 0, [&](int, double sz) {
      for_each_image_offset(cj.y - ci.y, n, L_, reach, [&](int, double sy) {
        for_each_image_offset(cj.x - ci.x, n, L_, reach, [&](int, double sx) { f(j, Vec3{sx, sy, sz}); });
      });
    });
  };
  // Class c holds reach R = c + 2, diameters below (2R - 1) w: a pair with
  // one of them is within cell_reach((d_i + (2R - 1) w) / 2) cells.
  for (int c = 0; c < large_.classes(); ++c)
    large_.for_each_near(fine, c, cell_reach(0.5 * (di + (2 * c + 3) * w), w), images);
}

// Calls f(j, shift) for every aggregate j (not i) that could touch i: those
// listed in the cells within i's reach, and the large ones at the images
// their pair's reach allows.
template <class F>
void AggregationEngine::for_each_candidate(int i, F&& f) const {
  for_each_cell_in_reach(i, reach_of(i), [&](const CellCoord& cell, const Vec3& shift) {
    for (int j = grid_->first_in_slot(grid_->slot(cell)); j >= 0; j = grid_->next(j))
      if (j != i) f(j, shift);
  });
  for_each_large_image(i, f);
}

// One walk over aggregate i's candidates, i at now_. Its event: the first
// face of its fine cell it will cross, or an earlier contact. With kOverlaps,
// also the slot of the smallest id it overlaps (-1 if none): a chain's test,
// which makes the event moot when it finds one. Both from the same
// separation, computed once.
template <bool kOverlaps>
AggregationEngine::Search AggregationEngine::search(int i) const {
  const CellExit exit = first_cell_exit(*grid_, fine_cell(i), m_[i].r, m_[i].v);
  double best = exit.time;
  int partner = -1, overlap = -1;
  const Motion& mi = m_[i];
  for_each_candidate(i, [&](int j, const Vec3& shift) {
    if (kOverlaps && overlap >= 0 && id_[j] > id_[overlap]) return;
    const Motion& mj = m_[j];
    const double dtj = now_ - mj.t;
    Vec3 dr, dv;
    for (int d = 0; d < 3; ++d) {
      dr[d] = mj.r[d] + mj.v[d] * dtj + shift[d] - mi.r[d];
      dv[d] = mj.v[d] - mi.v[d];
    }
    const double sigma = 0.5 * (diam_[i] + diam_[j]);
    if (kOverlaps && dot(dr, dr) < sigma * sigma) {
      overlap = j;
      return;
    }
    if (kOverlaps && overlap >= 0) return;
    const double t = time_to_contact_before(dr, dv, best, sigma * sigma);
    if (t < best) best = t, partner = j;
  });
  if (partner >= 0) return {Event::collision(now_ + best, partner, m_[partner].count), overlap};
  return {exit.face >= 0 ? Event::crossing(now_ + best, exit.face) : Event{}, overlap};
}

Event AggregationEngine::find_event(int i) const { return search<false>(i).event; }

void AggregationEngine::cross(int i, int face) {
  advance(i);
  if (large_.contains(i)) {
    large_.move(i, cell_across_face(*grid_, large_.fine_cell(i), face, L_, m_[i].r, image_[i]));
  } else {
    grid_->move(i, cell_across_face(*grid_, grid_->cell(i), face, L_, m_[i].r, image_[i]));
  }
}

Vec3 AggregationEngine::separation(int a, int b) const {
  Vec3 d;
  for (int k = 0; k < 3; ++k) {
    const double x = (m_[b].r[k] + m_[b].v[k] * (now_ - m_[b].t)) - (m_[a].r[k] + m_[a].v[k] * (now_ - m_[a].t));
    d[k] = x - L_ * std::round(x / L_);
  }
  return d;
}

// Merges a and b (both present) at now_ into the slot of the smaller id; returns it.
int AggregationEngine::merge(int a, int b) {
  const Vec3 d = separation(a, b);
  advance(a);
  advance(b);
  const int keep = id_[a] < id_[b] ? a : b, gone = keep == a ? b : a;
  const std::int32_t gone_id = id_[gone];
  const double ma = mass_[a], mb = mass_[b], M = ma + mb;
  Motion merged = m_[a];
  for (int k = 0; k < 3; ++k) {
    merged.r[k] = m_[a].r[k] + (mb / M) * d[k];  // centre of mass, in a's periodic frame
    merged.v[k] = (ma * m_[a].v[k] + mb * m_[b].v[k]) / M;
  }
  const Image frame = image_[a];
  const double da = diam_[a], db = diam_[b];
  large_.contains(gone) ? large_.remove(gone) : grid_->remove(gone);
  large_.contains(keep) ? large_.remove(keep) : grid_->remove(keep);
  m_[gone] = {Vec3{}, Vec3{}, now_, m_[gone].count + 1, -1};
  image_[gone] = {0, 0, 0};
  mass_[gone] = diam_[gone] = 0;
  id_[gone] = -1;
  calendar_.schedule(gone, Event{});
  merged.count = m_[keep].count + 1;
  m_[keep] = merged;
  image_[keep] = frame;
  mass_[keep] = M;
  diam_[keep] = geo_.merged_diameter(da, db);
  wrap_into_box(m_[keep].r, image_[keep], L_);
  place(keep, grid_->cell_of(m_[keep].r.x, m_[keep].r.y, m_[keep].r.z));
  --alive_;
  dmax_ = std::max(dmax_, diam_[keep]);
  ++c_.collisions;
  if (log_) log_->push_back({id_[keep], gone_id, now_});
  return keep;
}

// i and j touch: merge them, then whatever the new aggregate overlaps, until
// nothing does; then predict again. An aggregate that reaches half the box
// ends the run (RunStopped), but only once its chain is complete: the
// state then written holds no overlapping pair (stopping at once left the
// chain's pending merges as overlaps in the last frame).
void AggregationEngine::merge_chain(int i, int j) {
  int k = merge(i, j);
  bool rebuilt = false;
  while (true) {
    const bool too_large = 2.0 * dmax_ >= L_;
    if (!too_large && grid_outdated()) {
      rebuild_grid(&k);
      rebuilt = true;
    }
    // Overlaps with the new aggregate are found among its candidates, at the
    // images the cells allow (below the L/2 limit an overlap is through one
    // image only; beyond it the search visits every image its reach
    // covers); without one, the same walk gave its event.
    const Search found = search<true>(k);
    if (found.overlap < 0 && too_large) {
      too_large_ = true;
      throw_too_large();
    }
    if (found.overlap < 0) {
      if (rebuilt) {
        predict_all();
      } else {
        calendar_.schedule(k, found.event);
      }
      return;
    }
    k = merge(k, found.overlap);
  }
}

RunStatus AggregationEngine::run_until(double t_stop, std::int64_t max_events,
                                       const volatile std::sig_atomic_t* interrupt) {
  if (too_large_) throw_too_large();
  const std::int64_t last_event = c_.events + max_events;
  while (true) {
    if (RunStatus paused; pause_due(c_.events, last_event, interrupt, paused)) return paused;
    const int i = calendar_.top();
    if (i < 0) break;
    const Event ev = calendar_.event(i);
    if (ev.time > t_stop || ev.kind() == EventKind::kNone) break;
    now_ = ev.time;
    ++c_.events;
    if (ev.kind() == EventKind::kCrossing) {
      cross(i, ev.face());
      calendar_.schedule(i, find_event(i));
    } else if (!present(ev.partner()) || m_[ev.partner()].count != ev.partner_count) {  // partner changed since: stale
      ++c_.stale;
      advance(i);
      calendar_.schedule(i, find_event(i));
    } else {
      merge_chain(i, ev.partner());
    }
  }
  now_ = std::max(now_, t_stop);
  return RunStatus::kReached;
}

Observables AggregationEngine::observables() const {
  CompensatedSum energy, p[3];
  AggregateStats a;
  double total = 0;
  std::vector<std::int32_t> slot_of(m_.size(), -1);  // summed in id order, whatever the slots' order
  for (std::size_t s = 0; s < m_.size(); ++s)
    if (present(int(s))) slot_of[std::size_t(id_[s])] = std::int32_t(s);
  for (const std::int32_t i : slot_of) {
    if (i < 0) continue;
    const double mi = mass_[i];
    if (mi == 0) continue;
    ++a.aggregates;
    total += mi;
    a.largest_mass = std::max(a.largest_mass, mi);
    energy.add(0.5 * mi * dot(m_[i].v, m_[i].v));
    for (int d = 0; d < 3; ++d) p[d].add(mi * m_[i].v[d]);
  }
  a.mean_mass = a.aggregates ? total / double(a.aggregates) : 0;
  Observables o(now_, c_);
  o.kinetic_energy = energy.value() / double(m_.size());
  o.momentum = {p[0].value(), p[1].value(), p[2].value()};
  o.aggregates = a;
  return o;
}

}  // namespace coolgas
