#include "analyze/collapse/quality.h"

#include <algorithm>
#include <cmath>

namespace coolgas {
namespace {

bool weighted(const ScalingCurve& c) { return !c.ln_E_var.empty(); }

struct SquaredSum {
  double sum = 0, weight = 0;
};

// Adds w (ln y_a - ln y_b)^2 at a's points with scaled ln x in [lo, hi],
// over var_a + var_b when both curves are weighted (seed_weights.h). The
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
    const double d = a.ln_E[i] + dy - interpolate_clamped(b.ln_t, b.ln_E, lx - bx);
    const double var = weighted(a) && weighted(b) ? a.ln_E_var[i] + interpolate_clamped(b.ln_t, b.ln_E_var, lx - bx) : 1.0;
    s.sum += w * d * d / var;
    s.weight += w;
  }
}

double pair_mismatch(const ScalingCurve& a, const ScalingCurve& b, double theta, double z, double min_overlap) {
  const double lo = std::max(a.ln_t.front() + a.ln_x_shift(z), b.ln_t.front() + b.ln_x_shift(z));
  const double hi = std::min(a.ln_t.back() + a.ln_x_shift(z), b.ln_t.back() + b.ln_x_shift(z));
  const double penalty = no_overlap_penalty(weighted(a) && weighted(b));
  if (hi - lo < min_overlap) return penalty;
  SquaredSum s;
  add_pair_terms(a, b, theta, z, lo, hi, s);
  add_pair_terms(b, a, theta, z, lo, hi, s);
  return s.weight > 0 ? s.sum / s.weight : penalty;
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
