#include "simulate/engine.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "simulate/pair_prediction.h"

namespace coolgas {

namespace {
// Inelastic collapse shows as one particle colliding again and again while
// simulated time stops advancing: rule.collapse_limit() collisions in a row,
// each less than kStallGap (relative to 1 + t) after the particle's previous
// event.
constexpr double kStallGap = 1e-11;
constexpr int kInterruptCheckMask = 4095;  // look at the interrupt flag every 4096 events
}  // namespace

template <class Rule>
Engine<Rule>::Engine(Particles particles, const Rule& rule, double now, const EngineCounters& counters)
    : p_(std::move(particles)), rule_(rule), grid_(p_.L, 1.0, p_.size()), now_(now), c_(counters) {
  const std::size_t n = p_.size();
  event_time_.assign(n, kNever);
  partner_.assign(n, -1);
  count_.assign(n, 0);
  partner_count_.assign(n, 0);
  if constexpr (Rule::kDissipative) stall_.assign(n, 0);
  synchronize();
}

template <class Rule>
void Engine<Rule>::advance(int i) {
  const double dt = now_ - p_.t[i];
  Vec3& r = p_.r[i];
  const Vec3& v = p_.v[i];
  r.x += v.x * dt;
  r.y += v.y * dt;
  r.z += v.z * dt;
  p_.t[i] = now_;
}

template <class Rule>
void Engine<Rule>::synchronize() {
  const double L = p_.L;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    advance(int(i));
    for (int d = 0; d < 3; ++d) {
      double& x = p_.r[i][d];
      while (x >= L) x -= L, ++p_.image[i][d];
      while (x < 0) x += L, --p_.image[i][d];
      if (x >= L) x = 0;  // x was -tiny and x + L rounded up to L
    }
  }
  grid_.clear();
  for (std::size_t i = 0; i < p_.size(); ++i) grid_.insert(int(i), grid_.cell_of(p_.r[i].x, p_.r[i].y, p_.r[i].z));
  std::fill(count_.begin(), count_.end(), 0u);
  std::fill(stall_.begin(), stall_.end(), std::uint16_t{0});
  for (std::size_t i = 0; i < p_.size(); ++i) find_event(int(i));
  calendar_.reset(&event_time_, now_);
}

// The periodic shift that brings a particle of cell `to` next to one in cell
// `from` (the cells are neighbours, so each coordinate differs by -1, 0 or 1
// modulo the grid).
template <class Rule>
Vec3 Engine<Rule>::image_shift(int from, int to) const {
  const CellCoord a = grid_.coord(from), b = grid_.coord(to);
  auto shift = [&](int ca, int cb) { return cb - ca > 1 ? -p_.L : (ca - cb > 1 ? p_.L : 0.0); };
  return {shift(a.x, b.x), shift(a.y, b.y), shift(a.z, b.z)};
}

// Particle i is at now_; finds its earliest event: the first face of its cell
// it will cross, or an earlier contact with a particle in the 27 cells around.
template <class Rule>
void Engine<Rule>::find_event(int i) {
  const Vec3 ri = p_.r[i], vi = p_.v[i];
  const double w = grid_.width();
  const CellCoord c = grid_.coord(grid_.cell(i));
  const int cc[3] = {c.x, c.y, c.z};
  double best = kNever;
  int code = -1;
  for (int d = 0; d < 3; ++d) {
    if (vi[d] > 0) {
      const double t = std::max(0.0, ((cc[d] + 1) * w - ri[d]) / vi[d]);
      if (t < best) best = t, code = -1 - (2 * d + 1);
    } else if (vi[d] < 0) {
      const double t = std::max(0.0, (cc[d] * w - ri[d]) / vi[d]);
      if (t < best) best = t, code = -1 - 2 * d;
    }
  }
  const int n = grid_.cells_per_side();
  const double L = p_.L;
  for (int oz = -1; oz <= 1; ++oz) {
    int z = c.z + oz;
    double sz = 0;
    if (z < 0) z += n, sz = -L;
    else if (z >= n) z -= n, sz = L;
    for (int oy = -1; oy <= 1; ++oy) {
      int y = c.y + oy;
      double sy = 0;
      if (y < 0) y += n, sy = -L;
      else if (y >= n) y -= n, sy = L;
      for (int ox = -1; ox <= 1; ++ox) {
        int x = c.x + ox;
        double sx = 0;
        if (x < 0) x += n, sx = -L;
        else if (x >= n) x -= n, sx = L;
        for (int j = grid_.first(grid_.index({x, y, z})); j >= 0; j = grid_.next(j)) {
          if (j == i) continue;
          const double dtj = now_ - p_.t[j];
          const Vec3& rj = p_.r[j];
          const Vec3& vj = p_.v[j];
          const Vec3 dr{rj.x + vj.x * dtj + sx - ri.x, rj.y + vj.y * dtj + sy - ri.y, rj.z + vj.z * dtj + sz - ri.z};
          const Vec3 dv{vj.x - vi.x, vj.y - vi.y, vj.z - vi.z};
          const double t = time_to_contact(dr, dv);
          if (t < best) best = t, code = j;
        }
      }
    }
  }
  event_time_[i] = now_ + best;
  partner_[i] = code;
  if (code >= 0) partner_count_[i] = count_[code];
}

template <class Rule>
void Engine<Rule>::cross(int i, int code) {
  advance(i);
  const int face = -1 - code, d = face / 2;
  const bool up = face % 2 == 1;
  CellCoord c = grid_.coord(grid_.cell(i));
  int* cd = d == 0 ? &c.x : (d == 1 ? &c.y : &c.z);
  const int n = grid_.cells_per_side();
  if (up && ++*cd == n) {
    *cd = 0;
    p_.r[i][d] -= p_.L;
    ++p_.image[i][d];
  } else if (!up && --*cd < 0) {
    *cd = n - 1;
    p_.r[i][d] += p_.L;
    --p_.image[i][d];
  }
  grid_.move(i, grid_.index(c));
}

template <class Rule>
void Engine<Rule>::note_collision_gap(int i, double gap, int partner) {
  if constexpr (Rule::kDissipative) {  // elastic spheres cannot collapse
    if (gap > kStallGap * (1.0 + now_)) {
      stall_[i] = 0;
      return;
    }
    if (++stall_[i] < rule_.collapse_limit()) return;
    std::ostringstream s;
    s << "inelastic collapse at t = " << now_ << ": particle " << i << " collided " << rule_.collapse_limit()
      << " times in a row (last with particle " << partner << ") without simulated time advancing";
    throw CollapseError(s.str(), now_);
  }
}

template <class Rule>
void Engine<Rule>::collide(int i, int j) {
  note_collision_gap(i, now_ - p_.t[i], j);
  note_collision_gap(j, now_ - p_.t[j], i);
  advance(i);
  advance(j);
  const Vec3 s = image_shift(grid_.cell(i), grid_.cell(j));
  const Vec3& ri = p_.r[i];
  const Vec3& rj = p_.r[j];
  Vec3 n{rj.x + s.x - ri.x, rj.y + s.y - ri.y, rj.z + s.z - ri.z};
  const double inv = 1.0 / std::sqrt(dot(n, n));
  n = {n.x * inv, n.y * inv, n.z * inv};
  Vec3& vi = p_.v[i];
  Vec3& vj = p_.v[j];
  const double g = (vi.x - vj.x) * n.x + (vi.y - vj.y) * n.y + (vi.z - vj.z) * n.z;
  if (g > 0) {  // approaching (always, but for round-off at grazing contact)
    bool below = false;
    const double r = rule_.restitution(g, below);
    apply_restitution(vi, vj, n, g, r);
    c_.below_delta += below;
  }
  ++count_[i];
  ++count_[j];
  ++c_.collisions;
  if (log_) log_->push_back({std::min(i, j), std::max(i, j), now_});
}

template <class Rule>
RunStatus Engine<Rule>::run_until(double t_stop, std::int64_t max_events, const volatile std::sig_atomic_t* interrupt) {
  const std::int64_t last_event = c_.events + max_events;
  while (true) {
    if ((c_.events & kInterruptCheckMask) == 0) {
      if (interrupt && *interrupt) return RunStatus::kInterrupted;
      if (c_.events >= last_event) return RunStatus::kEventBudget;
    }
    const int i = calendar_.top();
    if (i < 0 || event_time_[i] > t_stop) break;
    now_ = event_time_[i];
    ++c_.events;
    const int code = partner_[i];
    if (code >= 0) {
      if (count_[code] != partner_count_[i]) {  // partner collided since: stale
        ++c_.stale;
        advance(i);
        find_event(i);
        calendar_.update(i);
        continue;
      }
      collide(i, code);
      find_event(i);
      calendar_.update(i);
      find_event(code);
      calendar_.update(code);
    } else {
      cross(i, code);
      find_event(i);
      calendar_.update(i);
    }
  }
  now_ = std::max(now_, t_stop);
  return RunStatus::kReached;
}

template class Engine<ElasticRule>;
template class Engine<ConstantRestitutionRule>;

}  // namespace coolgas
