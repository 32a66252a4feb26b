#include "simulate/run/run_eta.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

namespace {

constexpr double kEta = 1.83;            // E ~ x^-eta for x = t/L^(5/2) >> 1
constexpr double kFiniteSizeX = 2;       // where that tail exponent is taken to hold
constexpr double kLogSpacing = 1.01;

}  // namespace

void RunEta::add(const RunSample& s) {
  // The last sample always moves to the newest; the others stay 1 % of t apart.
  const std::size_t n = samples_.size();
  if (n >= 2 && s.t < samples_[n - 2].t * kLogSpacing) samples_.back() = s;
  else samples_.push_back(s);
}

double RunEta::collision_rate() const {
  if (samples_.size() < 2) return 0;
  const RunSample &a = samples_.front(), &b = samples_.back();
  return b.busy_seconds > a.busy_seconds ? (b.collisions - a.collisions) / (b.busy_seconds - a.busy_seconds) : 0;
}

double RunEta::expected_collisions(double t_end) const {
  if (samples_.empty()) return NAN;
  const RunSample& now = samples_.back();
  if (now.t >= t_end) return now.collisions;
  // Least squares of ln C on ln t over the last decade.
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const RunSample& s : samples_) {
    if (!(s.t > 0 && s.collisions > 0 && s.t >= now.t / 10)) continue;
    const double x = std::log(s.t), y = std::log(s.collisions);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  if (n < 2 || !(det > 1e-12 * n * sxx)) return NAN;
  const double a = std::max(0.0, (n * sxy - sx * sy) / det);
  const double t_fs = std::clamp(kFiniteSizeX * std::pow(L_, 2.5), now.t, t_end);
  const double tail = std::min(a, 1 - kEta / 2);
  return now.collisions * std::pow(t_fs / now.t, a) * std::pow(t_end / t_fs, tail);
}

double RunEta::seconds_left(double t_end) const {
  const double rate = collision_rate();
  const double expected = expected_collisions(t_end);
  if (!(rate > 0) || !std::isfinite(expected)) return NAN;
  return std::max(0.0, expected - samples_.back().collisions) / rate;
}

}  // namespace coolgas
