#include "simulate/engine/viscoelastic_restitution.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace coolgas {

namespace {

// Runge–Kutta steps per unit of reduced time: ε(0) = 1 to 1e-11 and C1 to
// 1e-7 (tests/physics/viscoelastic_restitution_test.cc).
constexpr double kStepsPerUnit = 4000;
// A collision lasts 3.2 reduced times at x = 0 and longer as x grows; far
// beyond what x <= kMaxX needs.
constexpr double kMaxDuration = 1e5;

struct State {
  double eta, rate;  // compression and its rate
};

State derivative(const State& s, double x) {
  const double root = std::sqrt(std::max(s.eta, 0.0));
  return {s.rate, -s.eta * root - x * root * s.rate};
}

State step(const State& s, double x, double h) {
  auto shifted = [&](const State& k, double f) { return State{s.eta + f * k.eta, s.rate + f * k.rate}; };
  const State k1 = derivative(s, x);
  const State k2 = derivative(shifted(k1, 0.5 * h), x);
  const State k3 = derivative(shifted(k2, 0.5 * h), x);
  const State k4 = derivative(shifted(k3, h), x);
  return {s.eta + h / 6 * (k1.eta + 2 * k2.eta + 2 * k3.eta + k4.eta),
          s.rate + h / 6 * (k1.rate + 2 * k2.rate + 2 * k3.rate + k4.rate)};
}

}  // namespace

double viscoelastic_pair_b(double b, double a1, double a2, double m1, double m2) {
  const double reduced_radius = a1 * a2 / (a1 + a2), reduced_mass = m1 * m2 / (m1 + m2);
  return b * std::pow(reduced_radius / 0.25, 0.2) * std::pow(reduced_mass / 0.5, -0.4);
}

double viscoelastic_restitution_exact(double x) {
  const double h = 1.0 / kStepsPerUnit;
  State s{0.0, 1.0};
  for (double t = h; t < kMaxDuration; t += h) {
    const State next = step(s, x, h);
    if (next.eta <= 0 && s.rate < 0) {  // back at zero compression during this step
      const double f = s.eta / (s.eta - next.eta);
      return -(s.rate + f * (next.rate - s.rate));
    }
    s = next;
  }
  throw std::logic_error("viscoelastic collision did not end: x too large");
}

ViscoelasticTable::ViscoelasticTable() {
  const int last = int(kMaxX * kKnotsPerUnit) + 2;
  for (int k = -1; k <= last; ++k) eps_.push_back(viscoelastic_restitution_exact(double(k) / kKnotsPerUnit));
}

const ViscoelasticTable& ViscoelasticTable::get() {
  static const ViscoelasticTable table;
  return table;
}

double ViscoelasticTable::operator()(double x) const {
  const double u = std::min(x, kMaxX) * kKnotsPerUnit;
  const int k = std::min(int(u), int(kMaxX * kKnotsPerUnit) - 1);  // x in [k, k + 1) knots
  const double f = u - k;
  const double* e = &eps_[std::size_t(k)];  // e[0..3]: knots k - 1 .. k + 2
  // Cubic Lagrange polynomial through the four knots around x.
  return -f * (f - 1) * (f - 2) / 6 * e[0] + (f + 1) * (f - 1) * (f - 2) / 2 * e[1] -
         (f + 1) * f * (f - 2) / 2 * e[2] + (f + 1) * f * (f - 1) / 6 * e[3];
}

}  // namespace coolgas
