#include "analyze/collapse/quality.h"

#include <algorithm>
#include <cmath>

namespace coolgas {
namespace {

// ln E of curve c at ln t = lt, linear in (ln t, ln E), clamped to its ends.
double interpolate_ln(const ScalingCurve& c, double lt) {
  if (lt <= c.ln_t.front()) return c.ln_E.front();
  if (lt >= c.ln_t.back()) return c.ln_E.back();
  const auto i = static_cast<std::size_t>(std::upper_bound(c.ln_t.begin(), c.ln_t.end(), lt) - c.ln_t.begin());
  const double u = (lt - c.ln_t[i - 1]) / (c.ln_t[i] - c.ln_t[i - 1]);
  return c.ln_E[i - 1] + u * (c.ln_E[i] - c.ln_E[i - 1]);
}

struct SquaredSum {
  double sum = 0, weight = 0;
};

// Adds w (ln y_a - ln y_b)^2 at a's points with scaled ln x in [lo, hi]. The
// weight w rises linearly from 0 over the first and last tenth of the
// overlap, so that a point entering or leaving the overlap as theta and z
// change does not make Q jump: a continuous Q keeps the simplex from sticking.
void add_pair_terms(const ScalingCurve& a, const ScalingCurve& b, double theta, double z, double lo, double hi,
                    SquaredSum& s) {
  const double ax = a.ln_x_shift(z), bx = b.ln_x_shift(z);
  const double dy = a.ln_y_shift(theta, z) - b.ln_y_shift(theta, z);
  const double ramp = 0.1 * (hi - lo);
  for (std::size_t i = 0; i < a.ln_t.size(); ++i) {
    const double lx = a.ln_t[i] + ax;
    if (lx <= lo || lx >= hi) continue;
    const double w = std::min({1.0, (lx - lo) / ramp, (hi - lx) / ramp});
    const double d = a.ln_E[i] + dy - interpolate_ln(b, lx - bx);
    s.sum += w * d * d;
    s.weight += w;
  }
}

double pair_mismatch(const ScalingCurve& a, const ScalingCurve& b, double theta, double z, double min_overlap) {
  const double lo = std::max(a.ln_t.front() + a.ln_x_shift(z), b.ln_t.front() + b.ln_x_shift(z));
  const double hi = std::min(a.ln_t.back() + a.ln_x_shift(z), b.ln_t.back() + b.ln_x_shift(z));
  if (hi - lo < min_overlap) return kNoOverlapPenalty;
  SquaredSum s;
  add_pair_terms(a, b, theta, z, lo, hi, s);
  add_pair_terms(b, a, theta, z, lo, hi, s);
  return s.weight > 0 ? s.sum / s.weight : kNoOverlapPenalty;
}

}  // namespace

double collapse_quality(const std::vector<ScalingCurve>& curves, double theta, double z, double min_overlap_decades) {
  const double min_overlap = min_overlap_decades * std::log(10.0);
  double total = 0;
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < curves.size(); ++i)
    for (std::size_t j = i + 1; j < curves.size(); ++j, ++pairs)
      total += pair_mismatch(curves[i], curves[j], theta, z, min_overlap);
  return pairs ? total / double(pairs) : 0;
}

}  // namespace coolgas
