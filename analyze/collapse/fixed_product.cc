#include "analyze/collapse/fixed_product.h"

#include <cmath>
#include <utility>

#include "analyze/collapse/quality.h"
#include "analyze/collapse/seed_weights.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {
namespace {
// Its own namespace: the unity build puts this file beside optimize.cc, whose
// helpers of the same names are in the same anonymous namespace.
namespace fixed {

struct Point {
  double u, q;  // u = ln z: z stays positive wherever the search goes
};

// Q at z = e^u, theta = P / z.
double quality_at(const std::vector<ScalingCurve>& curves, double product, double u, double min_overlap) {
  const double z = std::exp(u);
  return collapse_quality(curves, product / z, z, min_overlap);
}

// The minimum of Q along z: a bracket found by walking downhill from z0 with
// steps growing by the golden ratio (the first of 0.1 in ln z, about the
// paper's uncertainty of z), then golden-section search inside it down to
// 1e-9 in ln z. One dimension needs no simplex; the walk stops where Q stops
// falling, also on the flat no-overlap penalty, which the caller then refuses.
Point minimise(const std::vector<ScalingCurve>& curves, double product, double z0, double min_overlap) {
  constexpr double kGolden = 1.618033988749895, kStep = 0.1;
  auto q = [&](double u) { return quality_at(curves, product, u, min_overlap); };
  Point a{std::log(z0), 0}, b{a.u + kStep, 0};
  a.q = q(a.u);
  b.q = q(b.u);
  if (b.q > a.q) std::swap(a, b);  // downhill from a to b
  Point c{b.u + kGolden * (b.u - a.u), 0};
  c.q = q(c.u);
  for (int k = 0; c.q < b.q; ++k) {
    throw_if_interrupted("during the search for z; no table written");
    // 40 golden steps from 0.1 span 1e7 in ln z: Q has no minimum along z.
    if (k == 40) throw InputError("no minimum of the collapse quality along z with z theta fixed");
    a = b;
    b = c;
    c = {b.u + kGolden * (b.u - a.u), 0};
    c.q = q(c.u);
  }
  // b lies between a and c with Q(b) below both.
  double lo = std::min(a.u, c.u), hi = std::max(a.u, c.u);
  constexpr double kInv = 1 / kGolden;
  Point x1{hi - kInv * (hi - lo), 0}, x2{lo + kInv * (hi - lo), 0};
  x1.q = q(x1.u);
  x2.q = q(x2.u);
  while (hi - lo > 1e-9) {
    throw_if_interrupted("during the search for z; no table written");
    if (x1.q <= x2.q) {
      hi = x2.u;
      x2 = x1;
      x1 = {hi - kInv * (hi - lo), 0};
      x1.q = q(x1.u);
    } else {
      lo = x1.u;
      x1 = x2;
      x2 = {lo + kInv * (hi - lo), 0};
      x2.q = q(x2.u);
    }
  }
  Point best = x1.q <= x2.q ? x1 : x2;
  return b.q < best.q ? b : best;
}

}  // namespace fixed
}  // namespace

CollapseFit optimize_collapse_fixed_product(const std::vector<SizeEnsemble>& sizes, const CollapseSearch& search,
                                            double product) {
  if (!(std::isfinite(product) && product > 0))
    throw InputError("--z-theta " + format_number(product) + " is not allowed; it must be finite and > 0");
  if (!(std::isfinite(search.z0) && search.z0 > 0))
    throw InputError("--z " + format_number(search.z0) + " cannot start the search with z theta fixed; give z > 0");
  if (sizes.size() < 2)
    throw InputError("--optimize needs E(t) tables of at least 2 system sizes, got " + std::to_string(sizes.size()));
  std::size_t runs = 0;
  bool every_size_has_runs = true;
  for (const auto& s : sizes) {
    runs += s.runs.size();
    every_size_has_runs = every_size_has_runs && s.runs.size() >= 2;
  }
  if (search.bootstrap != 0 && !every_size_has_runs)
    throw InputError("--z-theta takes its errors from the jackknife over runs: give two or more tables (runs) of "
                     "every L, or --bootstrap 0 for the fit without errors");
  const std::vector<ScalingCurve> means = mean_curves(sizes);
  const fixed::Point best = fixed::minimise(means, product, search.z0, search.min_overlap_decades);
  const double z = std::exp(best.u);
  if (best.q >= no_overlap_penalty(!means.front().ln_E_var.empty()))
    throw InputError("no collapse found with z theta = " + format_number(product) + ": near z = " + format_number(z) +
                     " the scaled curves overlap by less than " + format_number(search.min_overlap_decades) +
                     " decades of x; start closer (--z) or lower --min-overlap");
  CollapseFit fit{product / z, z, best.q, 0, 0, 0, BootstrapKind::kRuns};
  if (search.bootstrap == 0) return fit;
  // The stratified delete-one jackknife over runs (optimize.h), each replica
  // searched again from the best z.
  double var_z = 0, var_theta = 0;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const std::size_t n = sizes[s].runs.size();
    std::vector<double> zs, thetas;
    for (std::size_t r = 0; r < n; ++r) {
      throw_if_interrupted(std::size_t(fit.replicas), runs, "jackknife replicas");
      std::vector<ScalingCurve> replica = means;
      replica[s] = ensemble_mean(without_run(sizes[s], r));
      double zr = 0;
      try {  // a signal inside the replica's search stops the loop of replicas
        zr = std::exp(fixed::minimise(replica, product, z, search.min_overlap_decades).u);
      } catch (const Interrupted& e) {
        throw interrupted_after(e.signal, std::size_t(fit.replicas), runs, "jackknife replicas");
      }
      zs.push_back(zr);
      thetas.push_back(product / zr);
      ++fit.replicas;
    }
    const double factor = double(n - 1) / double(n);
    var_z += factor * sum_of_squares(zs);
    var_theta += factor * sum_of_squares(thetas);
  }
  fit.z_err = std::sqrt(var_z);
  fit.theta_err = std::sqrt(var_theta);
  return fit;
}

}  // namespace coolgas
