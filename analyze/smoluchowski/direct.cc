#include "analyze/smoluchowski/direct.h"

#include <algorithm>

#include "common/interrupt.h"

namespace coolgas::smoluchowski {

long last_nonzero(const double* c, std::size_t n) {
  long top = static_cast<long>(n) - 1;
  while (top >= 0 && c[top] == 0) --top;
  return top;
}

DirectRhs::DirectRhs(const Kernel& kernel, std::int64_t M) : grid_(uniform_grid(M)), powers_(kernel, grid_.mass) {
  if (M > kTableLimit) return;
  table_.resize(M * M);
  for (std::int64_t i = 0; i < M; ++i)
    for (std::int64_t j = 0; j < M; ++j) table_[i * M + j] = powers_.k(i, j);
}

void DirectRhs::evaluate(const double* c, double* dcdt) {
  if (table_.empty()) {
    evaluate_with([this](long i, long j) { return powers_.k(i, j); }, c, dcdt);
  } else {
    const long M = static_cast<long>(grid_.size());
    const double* K = table_.data();
    evaluate_with([K, M](long i, long j) { return K[i * M + j]; }, c, dcdt);
  }
}

template <class K>
void DirectRhs::evaluate_with(const K& kernel, const double* c, double* dcdt) const {
  const long n = static_cast<long>(grid_.size());
  const long top = last_nonzero(c, grid_.size());
  // Index i holds mass i+1, so masses i+1 and j+1 make mass k+1 when i+j = k-1.
  for (long k = 0; k < n; ++k) {
    if (k % 1024 == 0 && interrupted()) return;  // the integrator stops the step (integrator.h)
    double gain = 0;
    for (long i = std::max(0L, k - 1 - top); i <= std::min(k - 1, top); ++i)
      gain += kernel(i, k - 1 - i) * c[i] * c[k - 1 - i];
    double loss = 0;
    if (k <= top && c[k] != 0)
      for (long j = 0; j <= top; ++j) loss += kernel(k, j) * c[j];
    dcdt[k] = 0.5 * gain - c[k] * loss;
  }
}

}  // namespace coolgas::smoluchowski
