#include "analyze/fit/haff.h"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_multifit_nlinear.h>
#include <gsl/gsl_vector.h>

#include <cmath>
#include <memory>
#include <vector>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {
namespace {

// Parameters p = (ln E0, ln t0): both stay positive without constraints.
struct Samples {
  std::vector<double> t, lnE, sigma;  // sigma of ln E (1 when unweighted)
};

int residuals(const gsl_vector* p, void* params, gsl_vector* f) {
  const auto& s = *static_cast<const Samples*>(params);
  const double lnE0 = gsl_vector_get(p, 0), t0 = std::exp(gsl_vector_get(p, 1));
  for (std::size_t i = 0; i < s.t.size(); ++i)
    gsl_vector_set(f, i, (lnE0 - 2 * std::log1p(s.t[i] / t0) - s.lnE[i]) / s.sigma[i]);
  return GSL_SUCCESS;
}

int jacobian(const gsl_vector* p, void* params, gsl_matrix* J) {
  const auto& s = *static_cast<const Samples*>(params);
  const double t0 = std::exp(gsl_vector_get(p, 1));
  for (std::size_t i = 0; i < s.t.size(); ++i) {
    const double u = s.t[i] / t0;
    gsl_matrix_set(J, i, 0, 1 / s.sigma[i]);
    gsl_matrix_set(J, i, 1, 2 * u / (1 + u) / s.sigma[i]);  // d/d(ln t0) of -2 ln(1 + t e^{-ln t0})
  }
  return GSL_SUCCESS;
}

// Haff's law is a straight line in 1/sqrt(E) = (1 + t/t0)/sqrt(E0): its
// least-squares line is the start, exact for noise-free Haff data.
std::pair<double, double> initial_guess(const FitData& d) {
  std::vector<double> y(d.t.size());
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = 1 / std::sqrt(d.E[i]);
  double a, b, c00, c01, c11, ss;
  gsl_fit_linear(d.t.data(), 1, y.data(), 1, y.size(), &a, &b, &c00, &c01, &c11, &ss);
  if (a > 0 && b > 0) return {1 / (a * a), a / b};
  return {d.E.front(), d.t.back()};  // not Haff-like at all: let the fit search
}

Samples make_samples(const FitData& d) {
  Samples s;
  for (std::size_t i = 0; i < d.t.size(); ++i) {
    if (!(d.t[i] >= 0) || !(d.E[i] > 0))
      throw InputError("Haff fit: point t = " + format_number(d.t[i]) + ", E = " + format_number(d.E[i]) +
                       " is not allowed (t >= 0 and E > 0 needed)");
    s.t.push_back(d.t[i]);
    s.lnE.push_back(std::log(d.E[i]));
    s.sigma.push_back(d.err.empty() ? 1.0 : d.err[i] / d.E[i]);
  }
  return s;
}

// gsl_multifit_nlinear_driver(max_iterations, tol, tol, tol) as GSL 2.7
// writes it, with a look at the interrupt flag before each iteration: one
// iteration over 10^7 rows (the table bound) takes a second, and GSL's own
// driver cannot be stopped (its callback cannot end it, and it ignores a
// residual function's error). Returns the driver's status.
int drive(gsl_multifit_nlinear_workspace* w, std::size_t max_iterations, double tol) {
  int info = 0, status = GSL_CONTINUE;
  std::size_t iterations = 0;
  while (status == GSL_CONTINUE && iterations < max_iterations) {
    throw_if_interrupted("during the Haff fit; no table written");
    // No progress at the first iteration: no step lowers the cost, more will not help.
    if (gsl_multifit_nlinear_iterate(w) == GSL_ENOPROG && iterations == 0) return GSL_EMAXITER;
    ++iterations;
    status = gsl_multifit_nlinear_test(tol, tol, tol, &info, w);
  }
  // Converged to machine precision is converged.
  if (status == GSL_ETOLF || status == GSL_ETOLX || status == GSL_ETOLG) status = GSL_SUCCESS;
  if (iterations >= max_iterations && status != GSL_SUCCESS) status = GSL_EMAXITER;
  return status;
}

}  // namespace

HaffFit fit_haff(const FitData& data) {
  const std::size_t n = data.t.size(), np = 2;
  if (n < 3) throw InputError("a Haff fit needs at least 3 points, got " + std::to_string(n));
  Samples s = make_samples(data);
  gsl_set_error_handler_off();
  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = jacobian;
  fdf.n = n;
  fdf.p = np;
  fdf.params = &s;
  gsl_multifit_nlinear_parameters fit_params = gsl_multifit_nlinear_default_parameters();
  std::unique_ptr<gsl_multifit_nlinear_workspace, void (*)(gsl_multifit_nlinear_workspace*)> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &fit_params, n, np), gsl_multifit_nlinear_free);
  const auto [E0_guess, t0_guess] = initial_guess(data);
  double start[2] = {std::log(E0_guess), std::log(t0_guess)};
  gsl_vector_view x0 = gsl_vector_view_array(start, np);
  gsl_multifit_nlinear_init(&x0.vector, &fdf, w.get());
  const int status = drive(w.get(), 500, 1e-12);
  if (status != GSL_SUCCESS)
    throw InputError(std::string("Haff fit did not converge (") + gsl_strerror(status) +
                     "); check the window holds the early, Haff-like part of E(t)");
  std::unique_ptr<gsl_matrix, void (*)(gsl_matrix*)> cov(gsl_matrix_alloc(np, np), gsl_matrix_free);
  gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w.get()), 0.0, cov.get());
  double chi2 = 0;
  gsl_blas_ddot(gsl_multifit_nlinear_residual(w.get()), gsl_multifit_nlinear_residual(w.get()), &chi2);

  HaffFit f;
  f.points = n;
  f.weighted = !data.err.empty();
  f.chi2_dof = n > np ? chi2 / double(n - np) : 0;
  // Without given errors the residual variance is the error scale.
  const double scale = f.weighted ? 1.0 : f.chi2_dof;
  const gsl_vector* p = gsl_multifit_nlinear_position(w.get());
  f.E0 = std::exp(gsl_vector_get(p, 0));
  f.t0 = std::exp(gsl_vector_get(p, 1));
  f.E0_err = f.E0 * std::sqrt(scale * gsl_matrix_get(cov.get(), 0, 0));  // d E0 = E0 d(ln E0)
  f.t0_err = f.t0 * std::sqrt(scale * gsl_matrix_get(cov.get(), 1, 1));
  return f;
}

}  // namespace coolgas
