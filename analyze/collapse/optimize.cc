#include "analyze/collapse/optimize.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>
#include <gsl/gsl_randist.h>
#include <gsl/gsl_rng.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "analyze/collapse/quality.h"
#include "analyze/collapse/seed_weights.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

struct Problem {
  const std::vector<ScalingCurve>* curves;
  double min_overlap_decades;
};

double quality_at(const gsl_vector* p, void* params) {
  const auto& pr = *static_cast<const Problem*>(params);
  return collapse_quality(*pr.curves, gsl_vector_get(p, 0), gsl_vector_get(p, 1), pr.min_overlap_decades);
}

struct Minimum {
  double theta, z, quality;
};

// One simplex run from (theta0, z0) until it shrinks below 1e-7.
Minimum simplex(const Problem& problem, double theta0, double z0) {
  Problem pr = problem;
  gsl_multimin_function f{quality_at, 2, &pr};
  std::unique_ptr<gsl_multimin_fminimizer, void (*)(gsl_multimin_fminimizer*)> m(
      gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, 2), gsl_multimin_fminimizer_free);
  double start[2] = {theta0, z0}, step[2] = {0.1, 0.2};  // steps of the size of the paper's uncertainties
  gsl_vector_view x = gsl_vector_view_array(start, 2), s = gsl_vector_view_array(step, 2);
  gsl_multimin_fminimizer_set(m.get(), &f, &x.vector, &s.vector);
  for (int iter = 0; iter < 2000; ++iter) {
    throw_if_interrupted("during the search for theta and z; no table written");
    if (gsl_multimin_fminimizer_iterate(m.get()) != GSL_SUCCESS) break;
    if (gsl_multimin_test_size(gsl_multimin_fminimizer_size(m.get()), 1e-7) == GSL_SUCCESS) break;
  }
  const gsl_vector* best = gsl_multimin_fminimizer_x(m.get());
  return {gsl_vector_get(best, 0), gsl_vector_get(best, 1), gsl_multimin_fminimizer_minimum(m.get())};
}

// The noise of the data makes Q slightly rough along its long theta-z
// valley, where a simplex can collapse early in a shallow dip; restarting it
// from its own result with full-size steps (the usual Nelder-Mead remedy)
// until Q stops improving finds the valley's floor.
Minimum minimise(const std::vector<ScalingCurve>& curves, double theta0, double z0, double min_overlap_decades) {
  const Problem pr{&curves, min_overlap_decades};
  Minimum best = simplex(pr, theta0, z0);
  for (int restart = 0; restart < 10; ++restart) {
    const Minimum next = simplex(pr, best.theta, best.z);
    if (!(next.quality < best.quality * (1 - 1e-9))) break;
    best = next;
  }
  return best;
}

// A replica's search from the best point: a signal inside it (a search is
// many simplex steps) stops the loop of replicas, "after DONE of TOTAL UNITS".
Minimum replica_minimum(const std::vector<ScalingCurve>& replica, const Minimum& best, double min_overlap,
                        std::size_t done, std::size_t total, const char* units) {
  try {
    return minimise(replica, best.theta, best.z, min_overlap);
  } catch (const Interrupted& e) {
    throw interrupted_after(e.signal, done, total, units);
  }
}

// Each curve's ln E moved by its standard error times a normal deviate.
std::vector<ScalingCurve> perturb(const std::vector<ScalingCurve>& curves, gsl_rng* rng) {
  std::vector<ScalingCurve> out = curves;
  for (auto& c : out)
    for (std::size_t i = 0; i < c.ln_E.size(); ++i) c.ln_E[i] += c.ln_E_err[i] * gsl_ran_gaussian(rng, 1.0);
  return out;
}

// Each curve's rows drawn with replacement, duplicates dropped (interpolation
// needs distinct times); at least 2 distinct rows are kept.
std::vector<ScalingCurve> resample_rows(const std::vector<ScalingCurve>& curves, gsl_rng* rng) {
  std::vector<ScalingCurve> out;
  for (const auto& c : curves) {
    std::vector<std::size_t> rows;
    do {
      rows.clear();
      for (std::size_t k = 0; k < c.t.size(); ++k) rows.push_back(gsl_rng_uniform_int(rng, c.t.size()));
      std::sort(rows.begin(), rows.end());
      rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    } while (rows.size() < 2);
    out.push_back(subset(c, rows));
  }
  return out;
}

std::size_t total_runs(const std::vector<SizeEnsemble>& sizes) {
  std::size_t n = 0;
  for (const auto& s : sizes) n += s.runs.size();
  return n;
}

// The stratified delete-one jackknife over runs (optimize.h).
// `means`: every size's mean curve (mean_curves(sizes)); a replica replaces one.
void jackknife_runs(const std::vector<SizeEnsemble>& sizes, const std::vector<ScalingCurve>& means,
                    const Minimum& best, double min_overlap, CollapseFit& fit) {
  double var_theta = 0, var_z = 0, var_product = 0;
  fit.replicas = 0;
  for (std::size_t s = 0; s < sizes.size(); ++s) {
    const std::size_t n = sizes[s].runs.size();
    std::vector<double> thetas, zs, products;
    for (std::size_t r = 0; r < n; ++r) {
      const auto done = std::size_t(fit.replicas);
      throw_if_interrupted(done, total_runs(sizes), "jackknife replicas");
      std::vector<ScalingCurve> replica = means;
      replica[s] = ensemble_mean(without_run(sizes[s], r));
      const Minimum m = replica_minimum(replica, best, min_overlap, done, total_runs(sizes), "jackknife replicas");
      thetas.push_back(m.theta);
      zs.push_back(m.z);
      products.push_back(m.z * m.theta);
      ++fit.replicas;
    }
    const double factor = double(n - 1) / double(n);
    var_theta += factor * sum_of_squares(thetas);
    var_z += factor * sum_of_squares(zs);
    var_product += factor * sum_of_squares(products);
  }
  fit.theta_err = std::sqrt(var_theta);
  fit.z_err = std::sqrt(var_z);
  fit.z_theta_err = std::sqrt(var_product);
}

void bootstrap(const std::vector<ScalingCurve>& curves, const Minimum& best, const CollapseSearch& search,
               CollapseFit& fit) {
  std::unique_ptr<gsl_rng, void (*)(gsl_rng*)> rng(gsl_rng_alloc(gsl_rng_mt19937), gsl_rng_free);
  gsl_rng_set(rng.get(), static_cast<unsigned long>(search.seed));
  std::vector<double> thetas, zs, products;
  for (int b = 0; b < search.bootstrap; ++b) {
    throw_if_interrupted(std::size_t(b), std::size_t(search.bootstrap), "bootstrap replicas");
    const auto replica =
        fit.kind == BootstrapKind::kErrors ? perturb(curves, rng.get()) : resample_rows(curves, rng.get());
    const Minimum m = replica_minimum(replica, best, search.min_overlap_decades, std::size_t(b),
                                      std::size_t(search.bootstrap), "bootstrap replicas");
    thetas.push_back(m.theta);
    zs.push_back(m.z);
    products.push_back(m.z * m.theta);
  }
  fit.replicas = search.bootstrap;
  const double dof = std::max(1.0, double(thetas.size()) - 1);
  fit.theta_err = std::sqrt(sum_of_squares(thetas) / dof);
  fit.z_err = std::sqrt(sum_of_squares(zs) / dof);
  fit.z_theta_err = std::sqrt(sum_of_squares(products) / dof);
}

BootstrapKind resampling_kind(const std::vector<SizeEnsemble>& sizes, const std::vector<ScalingCurve>& means) {
  if (std::all_of(sizes.begin(), sizes.end(), [](const auto& s) { return s.runs.size() >= 2; }))
    return BootstrapKind::kRuns;
  const bool errors = std::all_of(means.begin(), means.end(), [](const auto& c) { return !c.ln_E_err.empty(); });
  return errors ? BootstrapKind::kErrors : BootstrapKind::kRows;
}

}  // namespace

CollapseFit optimize_collapse(const std::vector<SizeEnsemble>& sizes, const CollapseSearch& search) {
  if (sizes.size() < 2)
    throw InputError("--optimize needs E(t) tables of at least 2 system sizes, got " + std::to_string(sizes.size()));
  // Each replica is a full optimisation (milliseconds): 1e5 of them take minutes; errors need about 100.
  if (search.bootstrap < 0 || search.bootstrap > 100000)
    throw InputError("--bootstrap " + std::to_string(search.bootstrap) + " is not allowed; it must be in [0, 100000]");
  gsl_set_error_handler_off();
  const std::vector<ScalingCurve> means = mean_curves(sizes);
  const Minimum best = minimise(means, search.theta0, search.z0, search.min_overlap_decades);
  if (best.quality >= no_overlap_penalty(!means.front().ln_E_var.empty()))
    throw InputError("no collapse found: near theta = " + format_number(best.theta) + ", z = " + format_number(best.z) +
                     " the scaled curves overlap by less than " + format_number(search.min_overlap_decades) +
                     " decades of x; start closer (--theta, --z) or lower --min-overlap");
  CollapseFit fit{best.theta, best.z, best.quality, 0, 0, 0, resampling_kind(sizes, means)};
  if (search.bootstrap == 0) return fit;
  if (fit.kind == BootstrapKind::kRuns) jackknife_runs(sizes, means, best, search.min_overlap_decades, fit);
  else bootstrap(means, best, search, fit);
  return fit;
}

CollapseFit optimize_collapse(const std::vector<ScalingCurve>& curves, const CollapseSearch& search) {
  std::vector<SizeEnsemble> sizes;
  for (const auto& c : curves) sizes.push_back(SizeEnsemble{c.L, {c}, {}});
  return optimize_collapse(sizes, search);
}

}  // namespace coolgas
