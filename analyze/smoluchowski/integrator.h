// Time stepping: an adaptive embedded Runge–Kutta method from GSL odeiv2,
// with the standard error control |err_i| <= atol + rtol |c_i| on every cell.
// Works in the ½-gain time of CoagulationRhs.
//
// After each accepted step, concentrations below zero are set to zero. They
// come only from round-off (FFT convolution noise, ~1e-16 of the peak) and
// from the step's truncation error on nearly empty cells, both within the
// requested tolerance; clamping keeps N(m,t) >= 0 as the physics demands.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "analyze/smoluchowski/grid.h"

namespace coolgas::smoluchowski {

enum class Stepper { Rk2, Rkf45, Rkck, Rk8pd };

// "rk2", "rkf45", "rkck", "rk8pd"; InputError naming the choices otherwise.
Stepper parse_stepper(const std::string& name);
std::string stepper_name(Stepper s);

struct IntegratorOptions {
  double rtol = 1e-8;        // relative tolerance per cell
  double atol = 1e-14;       // absolute tolerance, in concentration units (c_1(0) = 1)
  Stepper stepper = Stepper::Rkck;
  double first_step = 1e-4;  // trial first step; the controller adapts it at once
};

// The bytes an Integrator of `cells` cells allocates: its state and GSL's
// stepper stages and evolve buffers.
double integrator_bytes(double cells, Stepper s);

class Integrator {
 public:
  Integrator(CoagulationRhs& rhs, std::vector<double> c0, const IntegratorOptions& options);
  ~Integrator();
  Integrator(const Integrator&) = delete;
  Integrator& operator=(const Integrator&) = delete;

  // One adaptive step that does not pass t_limit.
  void step(double t_limit);
  // Steps until time() == t exactly (t >= time()); Interrupted
  // (common/interrupt.h) between two steps once SIGINT/SIGTERM arrived.
  void advance_to(double t);
  // Replaces the state (used to go back and refine a crossing time).
  void reset(double t, const std::vector<double>& c);

  double time() const { return t_; }
  const std::vector<double>& state() const { return c_; }
  long steps() const { return steps_; }
  long evaluations() const { return evaluations_; }

 private:
  struct Gsl;
  static int gsl_rhs(double t, const double* y, double* dydt, void* self);

  CoagulationRhs& rhs_;
  std::vector<double> c_;
  double t_ = 0, h_;
  long steps_ = 0, evaluations_ = 0;
  std::unique_ptr<Gsl> gsl_;
};

}  // namespace coolgas::smoluchowski
