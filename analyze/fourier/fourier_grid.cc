#include "analyze/fourier/fourier_grid.h"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

namespace coolgas {

FourierGrid::FourierGrid(int n, Geometry g) : n_(n), geo_(g) {
  if (n < 4 || n % 2) throw std::invalid_argument("FourierGrid: n must be even and >= 4, got " + std::to_string(n));
  const std::size_t count = std::size_t(padded()) * std::size_t(height()) * std::size_t(depth());
  data_ = fftw_alloc_real(count);
  if (!data_) throw std::bad_alloc();
  const int sides[3] = {n, n, n};  // the first d of them: the _3d, _2d and _1d plans' general form
  forward_ = fftw_plan_dft_r2c(g.d(), sides, data_, complex(), FFTW_ESTIMATE);
  inverse_ = fftw_plan_dft_c2r(g.d(), sides, complex(), data_, FFTW_ESTIMATE);
  clear();
}

FourierGrid::~FourierGrid() {
  fftw_destroy_plan(forward_);
  fftw_destroy_plan(inverse_);
  fftw_free(data_);
}

void FourierGrid::clear() { std::fill_n(data_, std::size_t(padded()) * std::size_t(height()) * std::size_t(depth()), 0.0); }
void FourierGrid::forward() { fftw_execute(forward_); }
void FourierGrid::inverse() { fftw_execute(inverse_); }

}  // namespace coolgas
