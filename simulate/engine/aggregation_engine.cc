#include "simulate/engine/aggregation_engine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "common/compensated_sum.h"
#include "simulate/engine/pair_prediction.h"

namespace coolgas {

namespace {
// Cells are made this much wider than the largest diameter when the grid is
// rebuilt, so that a rebuild (which predicts every aggregate again) is needed
// only after the largest volume has about doubled. Measured on W3 at N = 2e5
// (tests/bench/aggregation_bench.cc): 1.1 costs 21 CPU-s, 1.25 17, 1.4 16.4;
// wider cells make every prediction dearer.
constexpr double kWidthHeadroom = 1.25;
// The grid is rebuilt smaller once aggregates are this many times fewer than cells.
constexpr double kCellsPerAggregateLimit = 8.0;
}  // namespace

AggregateState AggregateState::unit_spheres(std::size_t n) {
  AggregateState a;
  a.mass.assign(n, 1.0);
  a.diameter.assign(n, 1.0);
  a.id.resize(n);
  for (std::size_t i = 0; i < n; ++i) a.id[i] = std::int32_t(i);
  return a;
}

AggregationEngine::AggregationEngine(Particles particles, AggregateState a, double now, const EngineCounters& counters)
    : L_(particles.L), now_(now), c_(counters) {
  const std::size_t n = particles.size();
  m_.resize(n);
  for (std::size_t i = 0; i < n; ++i) m_[i] = {particles.r[i], particles.v[i], particles.t[i], 0, -1};
  image_ = std::move(particles.image);
  mass_ = std::move(a.mass);
  diam_ = std::move(a.diameter);
  id_ = std::move(a.id);
  for (std::size_t i = 0; i < n; ++i) {
    if (!present(int(i))) continue;
    ++alive_;
    dmax_ = std::max(dmax_, diam_[i]);
  }
  event_time_.assign(n, kNever);
  partner_.assign(n, -1);
  partner_count_.assign(n, 0);
  synchronize();
}

Particles AggregationEngine::snapshot() const {
  Particles p;
  p.L = L_;
  p.resize(m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i) {
    p.r[i] = m_[i].r;
    p.v[i] = m_[i].v;
    p.t[i] = m_[i].t;
  }
  p.image = image_;
  return p;
}

void AggregationEngine::advance(int i) {
  Motion& m = m_[i];
  const double dt = now_ - m.t;
  for (int d = 0; d < 3; ++d) m.r[d] += m.v[d] * dt;
  m.t = now_;
}

void AggregationEngine::wrap(int i) {
  for (int d = 0; d < 3; ++d) {
    double& x = m_[i].r[d];
    while (x >= L_) x -= L_, ++image_[i][d];
    while (x < 0) x += L_, --image_[i][d];
    if (x >= L_) x = 0;  // x was -tiny and x + L rounded up to L
  }
}

// The state alone decides the grid, so a run resumed from a dump (taken
// right after synchronize()) rebuilds the same grid as the uninterrupted run.
void AggregationEngine::synchronize() {
  for (std::size_t i = 0; i < m_.size(); ++i) m_[i].count = 0;
  if (rebuild_grid()) predict_all();
}

bool AggregationEngine::grid_outdated() const {
  return dmax_ > grid_->width() ||
         (grid_->cells_per_side() > 3 && double(grid_->cell_count()) > kCellsPerAggregateLimit * double(alive_));
}

// Every aggregate to now_, wrapped, into a new grid whose cells are wider
// than the largest diameter and hold about one aggregate each. Returns false
// (aggregates moved and wrapped, no grid) when the largest aggregate is too
// wide for three cells per side; run_until() then reports it.
bool AggregationEngine::rebuild_grid() {
  for (std::size_t i = 0; i < m_.size(); ++i) {
    if (!present(int(i))) continue;
    advance(int(i));
    wrap(int(i));
  }
  const double spacing = std::cbrt(L_ * L_ * L_ / double(std::max<std::size_t>(alive_, 1)));
  const double widest = L_ / 3.0 / (1.0 + 1e-6);  // three cells per side, with CellGrid's own margin
  const double width = std::min(std::max(dmax_ * kWidthHeadroom, spacing), widest);
  too_large_ = width < dmax_;
  if (too_large_) return false;
  grid_ = std::make_unique<CellGrid>(L_, width, m_.size());
  for (std::size_t i = 0; i < m_.size(); ++i)
    if (present(int(i))) grid_->insert(int(i), grid_->cell_of(m_[i].r.x, m_[i].r.y, m_[i].r.z));
  return true;
}

void AggregationEngine::throw_too_large() const {
  std::ostringstream s;
  s << "aggregation at t = " << now_ << ": the largest aggregate (diameter " << dmax_
    << ") is wider than a third of the box (L = " << L_ << "), too large for the cell grid, with " << alive_
    << " aggregates left; use a larger system (more particles) to go on";
  throw AggregateTooLargeError(s.str(), now_);
}

void AggregationEngine::predict_all() {
  for (std::size_t i = 0; i < m_.size(); ++i) {
    if (present(int(i))) find_event(int(i));
    else event_time_[i] = kNever;
  }
  calendar_.resize(event_time_.size());
  for (std::size_t k = 0; k < event_time_.size(); ++k) calendar_.assign(int(k), {event_time_[k]});
  calendar_.reset(now_);
}

// Earliest contact of aggregate i with those of one cell, whose images are shifted by `shift`.
void AggregationEngine::scan_cell(int i, int cell, const Vec3& shift, double& best, int& code) const {
  const Motion& mi = m_[i];
  for (int j = grid_->first(cell); j >= 0; j = grid_->next(j)) {
    if (j == i) continue;
    const Motion& mj = m_[j];
    const double dtj = now_ - mj.t;
    Vec3 dr, dv;
    for (int d = 0; d < 3; ++d) {
      dr[d] = mj.r[d] + mj.v[d] * dtj + shift[d] - mi.r[d];
      dv[d] = mj.v[d] - mi.v[d];
    }
    const double sigma = 0.5 * (diam_[i] + diam_[j]);
    const double t = time_to_contact_before(dr, dv, best, sigma * sigma);
    if (t < best) best = t, code = j;
  }
}

// Aggregate i is at now_; its event is the first face of its cell it will
// cross, or an earlier contact with an aggregate in the 27 cells around.
void AggregationEngine::find_event(int i) {
  const Vec3 ri = m_[i].r, vi = m_[i].v;
  const CellCoord c = grid_->coord(grid_->cell(i));
  const CellExit exit = first_cell_exit(*grid_, grid_->cell(i), ri, vi);
  double best = exit.time;
  int code = exit.face >= 0 ? -1 - exit.face : -1;
  const int n = grid_->cells_per_side();
  auto wrapped = [n, this](int x, double& shift) {
    shift = x < 0 ? -L_ : (x >= n ? L_ : 0.0);
    return x < 0 ? x + n : (x >= n ? x - n : x);
  };
  for (int oz = -1; oz <= 1; ++oz)
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        Vec3 s;
        const int x = wrapped(c.x + ox, s.x), y = wrapped(c.y + oy, s.y), z = wrapped(c.z + oz, s.z);
        scan_cell(i, grid_->index({x, y, z}), s, best, code);
      }
  event_time_[i] = now_ + best;
  partner_[i] = code;
  if (code >= 0) partner_count_[i] = m_[code].count;
}

void AggregationEngine::cross(int i, int code) {
  advance(i);
  grid_->move(i, cell_across_face(*grid_, grid_->cell(i), -1 - code, L_, m_[i].r, image_[i]));
}

Vec3 AggregationEngine::separation(int a, int b) const {
  Vec3 d;
  for (int k = 0; k < 3; ++k) {
    const double x = (m_[b].r[k] + m_[b].v[k] * (now_ - m_[b].t)) - (m_[a].r[k] + m_[a].v[k] * (now_ - m_[a].t));
    d[k] = x - L_ * std::round(x / L_);
  }
  return d;
}

// Merges a and b (both present) at now_ into the smaller slot; returns it.
int AggregationEngine::merge(int a, int b) {
  const Vec3 d = separation(a, b);
  advance(a);
  advance(b);
  const int keep = std::min(a, b), gone = std::max(a, b);
  const double ma = mass_[a], mb = mass_[b], M = ma + mb;
  Motion merged = m_[a];
  for (int k = 0; k < 3; ++k) {
    merged.r[k] = m_[a].r[k] + (mb / M) * d[k];  // centre of mass, in a's periodic frame
    merged.v[k] = (ma * m_[a].v[k] + mb * m_[b].v[k]) / M;
  }
  const Image frame = image_[a];
  const double da = diam_[a], db = diam_[b];
  grid_->remove(gone);
  m_[gone] = {Vec3{}, Vec3{}, now_, m_[gone].count + 1, -1};
  image_[gone] = {0, 0, 0};
  mass_[gone] = diam_[gone] = 0;
  id_[gone] = -1;
  event_time_[gone] = kNever;
  calendar_.schedule(gone, {event_time_[gone]});
  merged.count = m_[keep].count + 1;
  m_[keep] = merged;
  image_[keep] = frame;
  mass_[keep] = M;
  diam_[keep] = std::cbrt(da * da * da + db * db * db);
  wrap(keep);
  grid_->move(keep, grid_->cell_of(m_[keep].r.x, m_[keep].r.y, m_[keep].r.z));
  --alive_;
  dmax_ = std::max(dmax_, diam_[keep]);
  ++c_.collisions;
  if (log_) log_->push_back({keep, gone, now_});
  return keep;
}

// The smallest id overlapping aggregate k at now_ (periodic), or -1.
int AggregationEngine::first_overlap(int k) {
  const CellCoord c = grid_->coord(grid_->cell(k));
  const int n = grid_->cells_per_side();
  int found = -1;
  for (int oz = -1; oz <= 1; ++oz)
    for (int oy = -1; oy <= 1; ++oy)
      for (int ox = -1; ox <= 1; ++ox) {
        const CellCoord nb{(c.x + ox + n) % n, (c.y + oy + n) % n, (c.z + oz + n) % n};
        for (int j = grid_->first(grid_->index(nb)); j >= 0; j = grid_->next(j)) {
          if (j == k || (found >= 0 && j > found)) continue;
          const Vec3 d = separation(k, j);
          const double sigma = 0.5 * (diam_[k] + diam_[j]);
          if (dot(d, d) < sigma * sigma) found = j;
        }
      }
  return found;
}

// i and j touch: merge them, then whatever the new aggregate overlaps, until
// nothing does; then predict again.
void AggregationEngine::merge_chain(int i, int j) {
  int k = merge(i, j);
  bool rebuilt = false;
  while (true) {
    if (grid_outdated()) {
      if (!rebuild_grid()) throw_too_large();
      rebuilt = true;
    }
    const int o = first_overlap(k);
    if (o < 0) break;
    k = merge(k, o);
  }
  if (rebuilt) {
    predict_all();
  } else {
    find_event(k);
    calendar_.schedule(k, {event_time_[k]});
  }
}

RunStatus AggregationEngine::run_until(double t_stop, std::int64_t max_events,
                                       const volatile std::sig_atomic_t* interrupt) {
  if (too_large_) throw_too_large();
  const std::int64_t last_event = c_.events + max_events;
  while (true) {
    if (RunStatus paused; pause_due(c_.events, last_event, interrupt, paused)) return paused;
    const int i = calendar_.top();
    if (i < 0 || event_time_[i] > t_stop) break;
    now_ = event_time_[i];
    ++c_.events;
    const int code = partner_[i];
    if (code >= 0 && (!present(code) || m_[code].count != partner_count_[i])) {  // partner changed since: stale
      ++c_.stale;
      advance(i);
      find_event(i);
      calendar_.schedule(i, {event_time_[i]});
    } else if (code >= 0) {
      merge_chain(i, code);
    } else {
      cross(i, code);
      find_event(i);
      calendar_.schedule(i, {event_time_[i]});
    }
  }
  now_ = std::max(now_, t_stop);
  return RunStatus::kReached;
}

AggregateSummary summarize_aggregates(const EngineBase& e) {
  const Motion* m = e.motion();
  const double* mass = e.masses();
  CompensatedSum energy, p[3];
  AggregateSummary s;
  double total = 0;
  for (std::size_t i = 0; i < e.size(); ++i) {
    const double mi = mass ? mass[i] : 1.0;
    if (mi == 0) continue;
    ++s.aggregates;
    total += mi;
    s.largest_mass = std::max(s.largest_mass, mi);
    energy.add(0.5 * mi * dot(m[i].v, m[i].v));
    for (int d = 0; d < 3; ++d) p[d].add(mi * m[i].v[d]);
  }
  s.mean_mass = s.aggregates ? total / double(s.aggregates) : 0;
  s.kinetic_energy = energy.value() / double(e.size());
  s.momentum = {p[0].value(), p[1].value(), p[2].value()};
  return s;
}

}  // namespace coolgas
