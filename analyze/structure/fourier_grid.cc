#include "analyze/structure/fourier_grid.h"

#include <algorithm>
#include <new>
#include <stdexcept>
#include <string>

namespace coolgas {

FourierGrid::FourierGrid(int n, int dimension) : n_(n), dimension_(dimension) {
  if (n < 4 || n % 2) throw std::invalid_argument("FourierGrid: n must be even and >= 4, got " + std::to_string(n));
  if (dimension < 1 || dimension > 3) throw std::invalid_argument("FourierGrid: dimension must be 1, 2 or 3");
  const std::size_t count = std::size_t(padded()) * std::size_t(height()) * std::size_t(depth());
  data_ = fftw_alloc_real(count);
  if (!data_) throw std::bad_alloc();
  if (dimension == 3) {
    forward_ = fftw_plan_dft_r2c_3d(n, n, n, data_, complex(), FFTW_ESTIMATE);
    inverse_ = fftw_plan_dft_c2r_3d(n, n, n, complex(), data_, FFTW_ESTIMATE);
  } else if (dimension == 2) {
    forward_ = fftw_plan_dft_r2c_2d(n, n, data_, complex(), FFTW_ESTIMATE);
    inverse_ = fftw_plan_dft_c2r_2d(n, n, complex(), data_, FFTW_ESTIMATE);
  } else {
    forward_ = fftw_plan_dft_r2c_1d(n, data_, complex(), FFTW_ESTIMATE);
    inverse_ = fftw_plan_dft_c2r_1d(n, complex(), data_, FFTW_ESTIMATE);
  }
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
