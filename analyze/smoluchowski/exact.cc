#include "analyze/smoluchowski/exact.h"

#include <cmath>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

bool has_exact_solution(const Kernel& kernel) {
  return kernel.kind == KernelKind::Constant || kernel.kind == KernelKind::Additive ||
         kernel.kind == KernelKind::Product;
}

namespace {

// Everything in logarithms: k^k and k! overflow long before the tails matter.
double log_constant(double k, double t) { return (k - 1) * std::log(t / 2) - (k + 1) * std::log1p(t / 2); }

double log_additive(double k, double t) {
  const double tau = -std::expm1(-t);
  return -t + (k - 1) * std::log(k * tau) - k * tau - std::lgamma(k + 1);
}

double log_product(double k, double t) {
  return (k - 3) * std::log(k) + (k - 1) * std::log(t) - k * t - std::lgamma(k);
}

}  // namespace

double exact_concentration(const Kernel& kernel, long k, double t) {
  if (k < 1) return 0;
  if (t == 0) return k == 1 ? 1.0 : 0.0;
  const double kk = static_cast<double>(k);
  switch (kernel.kind) {
    case KernelKind::Constant: return std::exp(log_constant(kk, t));
    case KernelKind::Additive: return std::exp(log_additive(kk, t));
    case KernelKind::Product:
      if (t > kProductGelationTime)
        throw InputError("product kernel: the exact solution holds only before gelation at t_g = 1, got t = " +
                         format_number(t));
      return std::exp(log_product(kk, t));
    default:
      throw InputError("kernel '" + kernel.text + "' has no exact solution; use constant, additive or product");
  }
}

}  // namespace coolgas::smoluchowski
