#include "simulate/run/run_eta.h"

#include <algorithm>
#include <cmath>

#include "simulate/engine/aggregation_engine.h"

namespace coolgas {

namespace {

// The rule's constants, chosen on the replayed C(t) of the demo's 46
// (run, t_end) cases (tests/bench/history.md, "ETA") and then checked on runs
// not used to choose them (other seeds, sizes, phi, r0 and delta; and gases
// with r0 = 0.7 and 0.9, which stay homogeneous for long).
constexpr double kFitWindow = 3;  // the exponent is fitted over t/3 .. t
// Before the knee the exponent is at least the clustering regime's. There
// (t = 1e2 up to the knee) the replayed gases grow C on average as t^0.42
// (delta = 1e-3) to t^0.6 (delta = 1e-4) and t^0.75 (delta = 1e-5) at
// phi = 0.208, r0 = 0.1; as t^0.42-0.49 at phi = 0.052; as t^0.35-0.44 at
// r0 = 0.5-0.9. The rate per particle ~ sqrt(E) with E ~ t^-6/5 would give
// 0.4: the collisions inside the clusters, below delta, fall off more slowly,
// the more so the denser and the more dissipative the gas and the smaller
// delta. The floor is linear in phi, r0 and log10 delta, within [0.3, 0.9].
// The paper's point, at which the floors below were measured.
constexpr double kPaperPhi = 0.208, kPaperR0 = 0.1, kPaperDelta = 1e-4;
constexpr double kClusteringPaper = 0.6;  // phi = 0.208, r0 = 0.1, delta = 1e-4
constexpr double kClusteringPerDecadeOfDelta = 0.1;  // per factor 10 smaller
constexpr double kClusteringPerPhi = 0.8;            // 0.08 per 0.1 of phi
constexpr double kClusteringPerR0 = -0.2;
constexpr double kClusteringLow = 0.3, kClusteringHigh = 0.9;
constexpr double kKnee = 0.5;  // the finite-size regime, from t = kKnee L^z on (z = 5/2 in 3D),
// where C grows at most as t^b, b = kTail (t / t_knee)^-kTailFall: the
// demo's gases fall from 0.25-0.3 at x = t/L^(5/2) = 2 to 0.1-0.13 at x = 10
// (tests/bench/history.md, "ETA").
constexpr double kTail = 0.35;
constexpr double kTailFall = 0.35;
constexpr int kStepsPerUnit = 64;  // the tail's integral: midpoints per unit of ln t
constexpr double kLogSpacing = 1.01;
// The crossings' floor moves with phi as the collisions' does (0.08 per 0.1
// of phi). The crossings' exponent over t = 1e2-1e4, r0 = 0.1, delta = 1e-4,
// logged from the engine's counters (tests/bench/history.md, "ETA"): 0.42-0.43
// at phi = 0.208 (L = 48), 0.39-0.40 at 0.156 (L = 70), 0.34-0.38 at 0.104
// (L = 80), 0.29-0.31 at 0.052 (L = 100); the rule gives 0.40, 0.36, 0.32, 0.28.
constexpr double kCrossingPaper = 0.4;  // 1 - theta/2, theta = 6/5, at phi = 0.208
constexpr double kCrossingPerPhi = 0.8;
constexpr double kCrossingLow = 0.2, kCrossingHigh = 0.5;
constexpr double kMeanFieldBA = 1.2;  // theta_BA^mf = 2d/(d + 2): n ~ (1 + t/tau)^-6/5
constexpr std::size_t kCostWindow = 6;  // the outputs an output's cost is fitted on
constexpr double kRateWindow = 0.25;  // the rate is taken over this last fraction of the busy time

double collisions_of(const RunSample& s) { return s.collisions; }
double events_of(const RunSample& s) { return s.events; }
double others_of(const RunSample& s) { return s.events - s.collisions; }  // crossings (and stale events)

// The least-squares slope of ln y on ln x over the points added; NaN
// without two distinct x.
class LogFit {
 public:
  void add(double x, double y) {
    if (!(x > 0 && y > 0)) return;
    const double u = std::log(x), v = std::log(y);
    n_ += 1, su_ += u, sv_ += v, suu_ += u * u, suv_ += u * v;
  }
  double slope() const {
    const double det = n_ * suu_ - su_ * su_;
    return n_ >= 2 && det > 1e-12 * n_ * suu_ ? (n_ * suv_ - su_ * sv_) / det : NAN;
  }

 private:
  double n_ = 0, su_ = 0, sv_ = 0, suu_ = 0, suv_ = 0;
};

// The slope of ln count on ln t over lo <= t <= hi.
template <class Count>
double log_slope(const std::vector<RunSample>& samples, Count count, double lo, double hi) {
  LogFit fit;
  for (const RunSample& s : samples)
    if (s.t >= lo && s.t <= hi) fit.add(s.t, count(s));
  return fit.slope();
}

// The aggregates left at t' = t e^u over those at t, for the local
// exponent beta of n now: (1 + t'/tau)^-6/5 through beta at t, or the
// power law t^-beta where beta is already steeper than the mean field's.
double aggregates_ratio(double beta, double u) {
  if (beta >= kMeanFieldBA) return std::exp(-beta * u);
  const double x = beta / (kMeanFieldBA - beta);  // t/tau: beta = 6/5 x/(1 + x)
  return std::pow((1 + x * std::exp(u)) / (1 + x), -kMeanFieldBA);
}

// Haff's law, E ~ (1 + t/tau)^-2 with a collision rate ~ sqrt(E), gives
// C ~ ln(1 + x), x = t/tau: its exponent h(x) = x / ((1 + x) ln(1 + x))
// falls from 1 to 0, and its integral over ln t is ln ln(1 + x).
double haff_exponent(double x) { return x / ((1 + x) * std::log1p(x)); }
double haff_integral(double x) { return std::log(std::log1p(x)); }

// The x at which Haff's exponent is a, for 0 < a < 1 (h falls with x).
double haff_x(double a) {
  double lo = -40, hi = 40;  // ln x
  for (int i = 0; i < 100; ++i) {
    const double mid = (lo + hi) / 2;
    (haff_exponent(std::exp(mid)) > a ? lo : hi) = mid;
  }
  return std::exp((lo + hi) / 2);
}

// The exponent ahead, as a function of u = ln(t'/t): Haff's, through a at
// u = 0; a itself if a >= 1 (a gas that does not cool) or a <= 0.
class HaffPath {
 public:
  explicit HaffPath(double a) : a_(a), haff_(a > 0 && a < 1), x0_(haff_ ? haff_x(a) : 0) {}
  // The integral of the exponent over [u0, u1].
  double integral(double u0, double u1) const {
    if (!haff_) return a_ * (u1 - u0);
    return haff_integral(x0_ * std::exp(u1)) - haff_integral(x0_ * std::exp(u0));
  }
  // The exponent itself at u.
  double at(double u) const { return haff_ ? haff_exponent(x0_ * std::exp(u)) : a_; }
  // Where the exponent falls to v: -inf if it is below v from the start, +inf if never.
  double crossing(double v) const {
    if (!haff_) return a_ > v ? INFINITY : -INFINITY;
    if (v <= 0) return INFINITY;
    if (v >= 1) return -INFINITY;
    return std::log(haff_x(v) / x0_);
  }

 private:
  double a_;
  bool haff_;
  double x0_;
};

// The integral over [u0, u1] of min(path, tail e^(-fall (u - u0))), by
// midpoints (the two may cross more than once).
double capped_integral(const HaffPath& path, double u0, double u1, double tail, double fall) {
  const int n = int(std::ceil((u1 - u0) * kStepsPerUnit));
  if (n <= 0) return 0;
  const double du = (u1 - u0) / n;
  double sum = 0;
  for (int i = 0; i < n; ++i) {
    const double v = (i + 0.5) * du;
    sum += std::min(path.at(u0 + v), tail * std::exp(-fall * v));
  }
  return sum * du;
}

}  // namespace

double log_growth(double t, double t_end, double a, double clustering, double t_knee, double tail, double tail_fall) {
  if (!(t_end > t)) return 0;
  const HaffPath path(a);
  const double u_end = std::log(t_end / t), u_knee = std::clamp(std::log(t_knee / t), 0.0, u_end);
  // Before the knee max(clustering, path): the path until it falls to the floor.
  const double floor_from = std::clamp(path.crossing(clustering), 0.0, u_knee);
  const double before = path.integral(0, floor_from) + clustering * (u_knee - floor_from);
  // After it min(path, the falling tail); the tail began at the knee, also
  // for a run already beyond it.
  const double tail_now = tail * std::pow(std::max(t / t_knee, 1.0), -tail_fall);
  return before + capped_integral(path, u_knee, u_end, tail_now, tail_fall);
}

double crossing_floor(double phi) {
  const double f = kCrossingPaper + kCrossingPerPhi * (phi - kPaperPhi);
  return std::isnan(f) ? kCrossingPaper : std::clamp(f, kCrossingLow, kCrossingHigh);
}

double clustering_floor(double phi, double r0, double delta) {
  const double f = kClusteringPaper + kClusteringPerDecadeOfDelta * std::log10(kPaperDelta / delta) +
                   kClusteringPerPhi * (phi - kPaperPhi) + kClusteringPerR0 * (r0 - kPaperR0);
  return std::isnan(f) ? kClusteringHigh : std::clamp(f, kClusteringLow, kClusteringHigh);
}

RunEta eta_without_cooling(const RunParameters&) { return RunEta(INFINITY); }
RunEta eta_of_cooling_gas(const RunParameters& p) { return RunEta(p.L); }
RunEta eta_of_inelastic_gas(const RunParameters& p) {
  const auto r0 = p.collision.find("r0"), delta = p.collision.find("delta");
  if (r0 == p.collision.end() || delta == p.collision.end()) return eta_of_cooling_gas(p);
  return RunEta(p.L, INFINITY, clustering_floor(p.phi, r0->second, delta->second), crossing_floor(p.phi));
}
RunEta eta_of_driven_gas(const RunParameters&) { return RunEta(INFINITY, INFINITY, 1.0); }
RunEta eta_of_aggregation(const RunParameters& p) {
  return RunEta::aggregation(p.L, double(p.N), AggregationEngine::kCellsPerAggregateLimit);
}

void RunEta::set_dimension(int d) { crossover_exponent_ = (d + 2) / 2.0; }

double RunEta::knee(double L) const { return kKnee * std::pow(L, crossover_exponent_); }

RunEta RunEta::aggregation(double L, double N, double regrid_factor) {
  RunEta eta(L, N - 1);
  eta.aggregates_ = N;
  eta.regrid_factor_ = regrid_factor;
  return eta;
}

void RunEta::add(const RunSample& s) {
  // The last sample always moves to the newest; the others stay 1 % of t apart.
  const std::size_t n = samples_.size();
  if (n >= 2 && s.t < samples_[n - 2].t * kLogSpacing) samples_.back() = s;
  else samples_.push_back(s);
}

double RunEta::collision_rate() const { return rate_of(collisions_of); }
double RunEta::event_rate() const { return rate_of(events_of); }

double RunEta::rate_of(Count count) const {
  if (samples_.size() < 2) return 0;
  const RunSample& b = samples_.back();
  // The newest sample at least kRateWindow of the busy time back (else the
  // first) and, under aggregation, with at least regrid_factor_ times the
  // aggregates left now: a window with a grid rebuild in it then spans the
  // rebuild's whole period, not just the rebuild (the ETA check's BA run,
  // N = 6.9e5, spends about 1 of its 14 engine seconds in the rebuild at
  // n = N/4; tests/bench/history.md, "ETA").
  const double from = (1 - kRateWindow) * b.busy_seconds;
  const double left = aggregates_ - b.collisions;
  const RunSample* by_time = &samples_.front();
  const RunSample* by_aggregates = std::isnan(aggregates_) ? &b : &samples_.front();
  for (const RunSample& s : samples_) {
    if (&s == &b) break;
    if (s.busy_seconds <= from) by_time = &s;
    if (aggregates_ - s.collisions >= regrid_factor_ * left) by_aggregates = &s;
  }
  const RunSample* a = std::min(by_time, by_aggregates);  // the samples are in time order
  const double r = (count(b) - count(*a)) / (b.busy_seconds - a->busy_seconds);
  return b.busy_seconds > a->busy_seconds && std::isfinite(r) ? r : 0;
}

double RunEta::exponent(double lo, double hi) const { return exponent_of(collisions_of, lo, hi); }

double RunEta::exponent_of(Count count, double lo, double hi) const {
  const double slope = log_slope(samples_, count, lo, hi);
  return std::isnan(slope) ? NAN : std::max(0.0, slope);
}

double RunEta::expected_collisions(double t_end) const {
  if (samples_.empty()) return NAN;
  const RunSample& now = samples_.back();
  if (now.t >= t_end) return now.collisions;
  const double t = now.t;
  if (!(samples_.front().t <= t / kFitWindow)) return NAN;  // not yet a whole fit window
  if (!std::isnan(aggregates_)) return expected_merges(t_end);
  const double a = exponent(t / kFitWindow, t);
  if (!std::isfinite(a)) return NAN;
  return std::min(most_, now.collisions * std::exp(log_growth(t, t_end, a, clustering_, knee(L_), kTail, kTailFall)));
}

double RunEta::expected_merges(double t_end) const {
  const RunSample& now = samples_.back();
  const double left = aggregates_ - now.collisions;
  if (!(left > 1)) return now.collisions;  // one aggregate cannot merge
  const auto aggregates = [&](const RunSample& s) { return aggregates_ - s.collisions; };
  const double beta = -log_slope(samples_, aggregates, now.t / kFitWindow, now.t);
  if (!(beta > 0)) return NAN;  // no merge over the fit window
  const double at_end = left * aggregates_ratio(beta, std::log(t_end / now.t));
  return now.collisions + left - std::max(at_end, 1.0);
}

double RunEta::frame_size(double t) const {
  if (std::isnan(aggregates_)) return 1;
  return aggregates_ - expected_collisions(t);
}

double RunEta::expected_events(double t_end) const {
  if (std::isnan(crossings_) || samples_.empty() || !(samples_.back().events >= samples_.back().collisions)) return NAN;
  const double collisions = expected_collisions(t_end);
  if (!std::isfinite(collisions)) return NAN;
  const RunSample& now = samples_.back();
  const double others = now.events - now.collisions;
  if (now.t >= t_end || !(others > 0)) return collisions + others;
  const double a = exponent_of(others_of, now.t / kFitWindow, now.t);
  if (!std::isfinite(a)) return NAN;
  // The floor, or the exponent now if it is lower: a gas whose temperature
  // still falls faster than t^-6/5 is taken to go on falling as fast, not faster.
  const double floor = std::min(a, crossings_);
  return collisions + others * std::exp(log_growth(now.t, t_end, a, floor, INFINITY, kTail, kTailFall));
}

double RunEta::seconds_left(double t_end) const {
  const double events = expected_events(t_end);
  const bool in_events = std::isfinite(events);
  const double rate = in_events ? event_rate() : collision_rate();
  const double expected = in_events ? events : expected_collisions(t_end);
  if (!(rate > 0) || !std::isfinite(expected)) return NAN;
  const RunSample& now = samples_.back();
  return std::max(0.0, expected - (in_events ? now.events : now.collisions)) / rate;
}

void OutputCost::add(double seconds, double size) {
  if (recent_.size() == kCostWindow) recent_.erase(recent_.begin());
  recent_.push_back({size, seconds});
}

double OutputCost::expected(double size, double otherwise) const {
  if (recent_.empty()) return otherwise;
  const Output& latest = recent_.back();
  if (!(size > 0 && latest.size > 0)) return latest.seconds;
  LogFit fit;
  for (const Output& o : recent_) fit.add(o.size, o.seconds);
  const double slope = fit.slope();
  const double gamma = std::isnan(slope) ? 0.0 : std::clamp(slope, 0.0, 1.0);
  return latest.seconds * std::pow(size / latest.size, gamma);
}

double output_seconds_left(const std::vector<double>& dump_sizes, double engine_seconds_left, double interval,
                           const OutputCost& dumps, const OutputCost& checkpoints) {
  double left = 0;
  for (double size : dump_sizes) left += dumps.expected(size, 0);
  const double checkpoint = checkpoints.latest(dumps.latest(0));
  return left + (1 + engine_seconds_left / std::max(interval, 1.0)) * checkpoint;
}

}  // namespace coolgas
