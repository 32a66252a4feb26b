#include "simulate/run/run_eta.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

namespace {

// The rule's constants (run_eta.h), chosen on the measured C(t) of the
// paper's gas (r0 = 0.1, delta = 1e-4; phi = 0.052, 0.104, 0.208; L = 20-50;
// t_end = 1e3, 1e4, 1e5) among fit windows of a factor 2-10, knees at
// 0.3-2 L^(5/2), tails 0.1-0.2 and floors 0.15-0.3: from 10 % to 90 % of the
// collisions, the collisions still expected were 0.33-2.4 times the truth
// (the rule before, a power law over the last decade with a knee at
// 2 L^(5/2): 0.29-33; dilute gases, whose exponent falls for decades, were
// the worst). Whole runs: tests/bench/eta_check.py.
constexpr double kFitWindow = 3;  // the exponent is fitted over t/3 .. t (and t/9 .. t/3 for its trend)
constexpr double kFloor = 0.25;   // a falling exponent stops falling here (beyond the knee)
// Before the knee the exponent is taken as at least 1 - theta/2 = 0.4, that
// of the clustering regime (E ~ t^-6/5, theta = 6/5, the paper's exponent;
// the rate per particle ~ sqrt(E)): every cooling gas goes through it on its
// way to the finite-size regime. Without it, an exponent measured low in the
// homogeneous phase (C ~ ln t under Haff's law) or while the clusters form
// was carried on, and runs were under-estimated to 0.18 of their collisions
// (the demo's runs, tests/bench/README.md "ETA").
constexpr double kClustering = 0.4;
constexpr double kKnee = 0.5;     // the finite-size regime, from t = kKnee L^(5/2) on,
constexpr double kTail = 0.2;     // where C grows as t^0.2 at most
constexpr double kLogSpacing = 1.01;
constexpr double kRateWindow = 0.25;  // the rate is taken over this last fraction of the busy time

// Integral of max(c, a + k u) du over [u0, u1], for k <= 0.
double above(double c, double a, double k, double u0, double u1) {
  const auto line = [&](double p, double q) { return a * (q - p) + k * (q * q - p * p) / 2; };
  if (k == 0) return std::max(c, a) * (u1 - u0);
  const double cross = std::clamp((c - a) / k, u0, u1);  // the line is above c before this
  return line(u0, cross) + c * (u1 - cross);
}

}  // namespace

double log_growth(double t, double t_end, double a, double trend, double floor, double t_knee, double tail) {
  if (!(t_end > t)) return 0;
  const double k = std::min(trend, 0.0), f = std::min(floor, a);
  const double u_end = std::log(t_end / t), u_knee = std::clamp(std::log(t_knee / t), 0.0, u_end);
  // Before the knee: max(f, a + k u). After it: capped at tail, i.e.
  // min(max(f, line), tail) = max(f, line) - max(0, line - tail) when tail > f.
  const double before = above(f, a, k, 0, u_knee);
  const double span = u_end - u_knee;
  const double after = tail <= f ? tail * span
                                 : above(f, a, k, u_knee, u_end) - (above(tail, a, k, u_knee, u_end) - tail * span);
  return before + after;
}

void RunEta::add(const RunSample& s) {
  // The last sample always moves to the newest; the others stay 1 % of t apart.
  const std::size_t n = samples_.size();
  if (n >= 2 && s.t < samples_[n - 2].t * kLogSpacing) samples_.back() = s;
  else samples_.push_back(s);
}

double RunEta::collision_rate() const {
  if (samples_.size() < 2) return 0;
  const RunSample& b = samples_.back();
  // The newest sample at least kRateWindow of the busy time back (else the first).
  const double from = (1 - kRateWindow) * b.busy_seconds;
  const RunSample* a = &samples_.front();
  for (const RunSample& s : samples_)
    if (s.busy_seconds <= from && &s != &b) a = &s;
  return b.busy_seconds > a->busy_seconds ? (b.collisions - a->collisions) / (b.busy_seconds - a->busy_seconds) : 0;
}

double RunEta::exponent(double lo, double hi) const {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const RunSample& s : samples_) {
    if (!(s.t > 0 && s.collisions > 0 && s.t >= lo && s.t <= hi)) continue;
    const double x = std::log(s.t), y = std::log(s.collisions);
    n += 1, sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  const double det = n * sxx - sx * sx;
  if (n < 2 || !(det > 1e-12 * n * sxx)) return NAN;
  return std::max(0.0, (n * sxy - sx * sy) / det);
}

double RunEta::expected_collisions(double t_end) const {
  if (samples_.empty()) return NAN;
  const RunSample& now = samples_.back();
  if (now.t >= t_end) return now.collisions;
  const double t = now.t, w = kFitWindow;
  if (!(samples_.front().t <= t / w)) return NAN;  // not yet a whole fit window
  const double measured = exponent(t / w, t);
  if (!std::isfinite(measured)) return NAN;
  const double before = exponent(t / (w * w), t / w);
  const double trend = std::isfinite(before) ? (measured - before) / std::log(w) : 0;
  const double knee = kKnee * std::pow(L_, 2.5);
  const bool clustering_ahead = t < knee;
  const double a = clustering_ahead ? std::max(measured, kClustering) : measured;
  const double floor = clustering_ahead ? kClustering : kFloor;
  return std::min(most_, now.collisions * std::exp(log_growth(t, t_end, a, trend, floor, knee, kTail)));
}

double RunEta::seconds_left(double t_end) const {
  const double rate = collision_rate();
  const double expected = expected_collisions(t_end);
  if (!(rate > 0) || !std::isfinite(expected)) return NAN;
  return std::max(0.0, expected - samples_.back().collisions) / rate;
}

}  // namespace coolgas
