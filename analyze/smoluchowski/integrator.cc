#include "analyze/smoluchowski/integrator.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

Stepper parse_stepper(const std::string& name) {
  if (name == "rk2") return Stepper::Rk2;
  if (name == "rkf45") return Stepper::Rkf45;
  if (name == "rkck") return Stepper::Rkck;
  if (name == "rk8pd") return Stepper::Rk8pd;
  throw InputError("stepper '" + name + "' is not known; use rk2, rkf45, rkck or rk8pd");
}

std::string stepper_name(Stepper s) {
  switch (s) {
    case Stepper::Rk2: return "rk2";
    case Stepper::Rkf45: return "rkf45";
    case Stepper::Rkck: return "rkck";
    case Stepper::Rk8pd: return "rk8pd";
  }
  return "?";
}

namespace {
const gsl_odeiv2_step_type* step_type(Stepper s) {
  switch (s) {
    case Stepper::Rk2: return gsl_odeiv2_step_rk2;
    case Stepper::Rkf45: return gsl_odeiv2_step_rkf45;
    case Stepper::Rkck: return gsl_odeiv2_step_rkck;
    case Stepper::Rk8pd: return gsl_odeiv2_step_rk8pd;
  }
  return gsl_odeiv2_step_rkck;
}
}  // namespace

double integrator_bytes(double cells, Stepper s) {
  // Vectors of GSL's steppers (gsl/ode-initval2/*.c): rk2 k1-k3, y0, ytmp;
  // rkf45 and rkck k1-k6, y0, ytmp; rk8pd k[13], y0, ytmp, and more. The
  // evolve object: y0, yerr, dydt_in, dydt_out. The state c_.
  double stages = 0;
  switch (s) {
    case Stepper::Rk2: stages = 5; break;
    case Stepper::Rkf45:
    case Stepper::Rkck: stages = 8; break;
    case Stepper::Rk8pd: stages = 18; break;
  }
  return (stages + 4 + 1) * cells * sizeof(double);
}

struct Integrator::Gsl {
  gsl_odeiv2_system sys{};
  gsl_odeiv2_step* step = nullptr;
  gsl_odeiv2_control* control = nullptr;
  gsl_odeiv2_evolve* evolve = nullptr;
  ~Gsl() {
    if (evolve) gsl_odeiv2_evolve_free(evolve);
    if (control) gsl_odeiv2_control_free(control);
    if (step) gsl_odeiv2_step_free(step);
  }
};

// An evaluation may stop early once a signal arrived (a long one looks at
// the flag, CoagulationRhs::evaluate); GSL is then told to stop
// (GSL_EBADFUNC returns at once from the step), and step() throws
// Interrupted, never crossing GSL's C frames with an exception.
int Integrator::gsl_rhs(double, const double* y, double* dydt, void* self) {
  auto* me = static_cast<Integrator*>(self);
  if (interrupted()) return GSL_EBADFUNC;
  me->rhs_.evaluate(y, dydt);
  ++me->evaluations_;
  return interrupted() ? GSL_EBADFUNC : GSL_SUCCESS;
}

Integrator::Integrator(CoagulationRhs& rhs, std::vector<double> c0, const IntegratorOptions& o)
    : rhs_(rhs), c_(std::move(c0)), h_(o.first_step), gsl_(std::make_unique<Gsl>()) {
  if (!(o.rtol > 0) || !(o.atol > 0))
    throw InputError("tolerances must be > 0, got rtol " + format_number(o.rtol) + " and atol " +
                     format_number(o.atol));
  // GSL's default handler aborts the program; we report failures ourselves.
  gsl_set_error_handler_off();
  const std::size_t n = c_.size();
  gsl_->sys = {&Integrator::gsl_rhs, nullptr, n, this};
  gsl_->step = gsl_odeiv2_step_alloc(step_type(o.stepper), n);
  gsl_->control = gsl_odeiv2_control_y_new(o.atol, o.rtol);
  gsl_->evolve = gsl_odeiv2_evolve_alloc(n);
  if (!gsl_->step || !gsl_->control || !gsl_->evolve) throw std::bad_alloc();
}

Integrator::~Integrator() = default;

void Integrator::step(double t_limit) {
  const int status = gsl_odeiv2_evolve_apply(gsl_->evolve, gsl_->control, gsl_->step, &gsl_->sys, &t_, t_limit,
                                             &h_, c_.data());
  if (status == GSL_EBADFUNC && interrupted()) {
    gsl_odeiv2_evolve_reset(gsl_->evolve);
    throw Interrupted(interrupt_signal(), "during a step from t = " + format_number(t_) +
                                              "; the rows written so far are complete, the '# end' line is missing");
  }
  if (status != GSL_SUCCESS)
    throw std::runtime_error("time step failed at t = " + format_number(t_) + " (GSL: " + gsl_strerror(status) + ")");
  ++steps_;
  for (double& x : c_) x = std::max(x, 0.0);
}

void Integrator::advance_to(double t) {
  while (t_ < t) {
    if (interrupted())
      throw Interrupted(interrupt_signal(), "at t = " + format_number(t_) + " of a solution to t = " + format_number(t) +
                                                "; the rows written so far are complete");
    step(t);
  }
}

void Integrator::reset(double t, const std::vector<double>& c) {
  t_ = t;
  c_ = c;
  gsl_odeiv2_evolve_reset(gsl_->evolve);
  gsl_odeiv2_step_reset(gsl_->step);
}

}  // namespace coolgas::smoluchowski
