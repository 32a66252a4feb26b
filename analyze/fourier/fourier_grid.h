// A periodic n^3 grid of real numbers and its discrete Fourier transform, in
// place, with FFTW (real-to-complex, FFTW_ESTIMATE: the plan, and so the
// arithmetic, is the same on every run; a measured plan could differ run to run).
//
// Layout: point (ix, iy, iz) at position (ix, iy, iz) * L/n holds
// real()[ix + P*(iy + n*iz)], P = 2(n/2 + 1) (the padding FFTW needs for an
// in-place r2c transform). After forward(), mode (kx, ky, kz) with
// 0 <= kx <= n/2 is complex()[kx + (n/2+1)*(iy + n*iz)], where iy, iz are
// ky, kz mod n; the other half of k space is its complex conjugate.
// The transform is unnormalised: forward() gives sum_x f(x) e^{-i k.x}.
// A 2D grid (disks) is the same with one plane: n^2 points, iz = kz = 0; a
// 1D grid (rods) with one row of that plane: n points, iy = iz = 0.
//
// A transform is one FFTW call, which a signal cannot stop in its middle
// (FFTW has no hook for it; splitting it into planes and columns would
// change its arithmetic): the tool acts on SIGINT/SIGTERM/SIGHUP at its
// next look after the call. What keeps a call short is --grid's limit of
// 1024 points a side (structure_table.cc): about 30 s of CPU at the limit,
// a few seconds for 512^3 (tests/bench/README.md, `structure_bench fft N`).
#pragma once
#include <fftw3.h>

#include <cstddef>
#include <cstdint>

#include "common/geometry.h"

namespace coolgas {

class FourierGrid {
 public:
  FourierGrid(int n, Geometry g);  // n even, >= 4
  ~FourierGrid();
  FourierGrid(const FourierGrid&) = delete;
  FourierGrid& operator=(const FourierGrid&) = delete;

  int n() const { return n_; }
  int dimension() const { return geo_.d(); }
  Geometry geometry() const { return geo_; }
  int depth() const { return geo_.along(2, n_); }   // planes along z
  int height() const { return geo_.along(1, n_); }  // rows along y in a plane
  int padded() const { return 2 * (n_ / 2 + 1); }     // P, real numbers per x row
  int half() const { return n_ / 2 + 1; }             // complex modes per x row
  std::int64_t modes() const { return std::int64_t(half()) * height() * depth(); }
  std::int64_t real_index(int ix, int iy, int iz) const { return ix + std::int64_t(padded()) * (iy + std::int64_t(n_) * iz); }

  double* real() { return data_; }
  const double* real() const { return data_; }
  fftw_complex* complex() { return reinterpret_cast<fftw_complex*>(data_); }
  const fftw_complex* complex() const { return reinterpret_cast<const fftw_complex*>(data_); }

  void clear();     // every real point (and the padding) to 0
  void forward();   // real -> complex
  void inverse();   // complex (half space) -> real, unnormalised (n^d times the inverse DFT)

  // Signed wave number of row index i (0..n-1): i for i <= n/2, else i - n.
  int signed_index(int i) const { return i <= n_ / 2 ? i : i - n_; }

 private:
  int n_;
  Geometry geo_;
  double* data_;
  fftw_plan forward_, inverse_;
};

}  // namespace coolgas
