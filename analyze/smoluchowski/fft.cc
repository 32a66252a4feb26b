#include "analyze/smoluchowski/fft.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <new>

#include "analyze/smoluchowski/direct.h"
#include "common/interrupt.h"

namespace coolgas::smoluchowski {

namespace {
constexpr std::size_t kMinActive = 64;  // below this an FFT costs nothing anyway
}

FftRhs::FftRhs(const Kernel& kernel, std::int64_t M, double floor)
    : grid_(uniform_grid(M)), powers_(kernel, grid_.mass), floor_(floor) {
  max_length_ = 2 * std::bit_ceil(static_cast<std::size_t>(M));
  const std::size_t nspec = powers_.table.size() + 1;
  real_ = fftw_alloc_real(max_length_);
  spectra_ = fftw_alloc_complex(nspec * (max_length_ / 2 + 1));
  if (!real_ || !spectra_) throw std::bad_alloc();
  plans_.resize(std::bit_width(max_length_) + 1);
}

FftRhs::~FftRhs() {
  for (auto& p : plans_) {
    if (p.forward) fftw_destroy_plan(p.forward);
    if (p.inverse) fftw_destroy_plan(p.inverse);
  }
  fftw_free(real_);
  fftw_free(spectra_);
}

const FftRhs::Plans& FftRhs::plans_for(std::size_t length) {
  Plans& p = plans_[std::bit_width(length)];
  if (!p.forward) {
    const int n = static_cast<int>(length);
    p.forward = fftw_plan_dft_r2c_1d(n, real_, spectra_, FFTW_ESTIMATE);
    p.inverse = fftw_plan_dft_c2r_1d(n, spectra_, real_, FFTW_ESTIMATE);
  }
  return p;
}

void FftRhs::grow_active(const double* c) {
  const std::size_t M = grid_.size();
  double peak = 0;
  for (std::size_t i = 0; i < M; ++i) peak = std::max(peak, std::abs(c[i]));
  long top = static_cast<long>(M) - 1;
  while (top >= 0 && std::abs(c[top]) <= floor_ * peak) --top;
  std::size_t need = 2 * static_cast<std::size_t>(top + 1);
  // The first state (the initial condition) is taken in full: nothing given
  // by the user is dropped however small.
  if (active_ == 0) need = std::max(need, static_cast<std::size_t>(last_nonzero(c, M) + 1));
  need = std::min(M, std::bit_ceil(std::max(need, kMinActive)));
  active_ = std::max(active_, need);
}

void FftRhs::gain(const double* c, std::size_t length, double* out) {
  const Plans& plans = plans_for(length);
  const std::size_t nf = length / 2 + 1, E = powers_.table.size();
  for (std::size_t e = 0; e < E; ++e) {
    if (interrupted()) return;  // a transform of 2^28 points takes seconds; the integrator stops the step
    const double* pw = powers_.table[e].data();
    for (std::size_t i = 0; i < active_; ++i) real_[i] = pw[i] * c[i];
    std::fill(real_ + active_, real_ + length, 0.0);
    fftw_execute_dft_r2c(plans.forward, real_, spectra_ + e * nf);
  }
  fftw_complex* sum = spectra_ + E * nf;
  std::fill(&sum[0][0], &sum[0][0] + 2 * nf, 0.0);
  for (const auto& t : powers_.terms) {
    const fftw_complex* a = spectra_ + t.p * nf;
    const fftw_complex* b = spectra_ + t.q * nf;
    for (std::size_t f = 0; f < nf; ++f) {
      sum[f][0] += t.c * (a[f][0] * b[f][0] - a[f][1] * b[f][1]);
      sum[f][1] += t.c * (a[f][0] * b[f][1] + a[f][1] * b[f][0]);
    }
  }
  fftw_execute_dft_c2r(plans.inverse, sum, real_);
  // Index i holds mass i+1: masses i+1 and j+1 make mass k+1 at i+j = k-1.
  const double scale = 1.0 / static_cast<double>(length);
  out[0] = 0;
  for (std::size_t k = 1; k < active_; ++k) out[k] = real_[k - 1] * scale;
}

void FftRhs::loss_moments(const double* c, std::vector<double>& mu) const {
  mu.assign(powers_.table.size(), 0.0);
  for (std::size_t e = 0; e < mu.size(); ++e) {
    const double* pw = powers_.table[e].data();
    double s = 0;
    for (std::size_t j = 0; j < active_; ++j) s += pw[j] * c[j];
    mu[e] = s;
  }
}

void FftRhs::evaluate(const double* c, double* dcdt) {
  grow_active(c);
  gain(c, 2 * std::bit_ceil(active_), dcdt);
  std::vector<double> mu;
  loss_moments(c, mu);
  for (const auto& t : powers_.terms) {
    const double* pp = powers_.table[t.p].data();
    const double* pq = powers_.table[t.q].data();
    const double mp = mu[t.p], mq = mu[t.q];
    for (std::size_t k = 0; k < active_; ++k) dcdt[k] -= c[k] * t.c * (pp[k] * mq + pq[k] * mp);
  }
  std::fill(dcdt + active_, dcdt + grid_.size(), 0.0);
}

}  // namespace coolgas::smoluchowski
