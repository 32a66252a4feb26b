// The fast method: for K = Σ_t c_t (i^p j^q + i^q j^p) the gain term is
//   ½ Σ_{i+j=k} K c_i c_j = Σ_t c_t (A_p * A_q)_k,   A_e(i) = i^e c_i,
// a sum of linear convolutions, done with FFTW in O(M log M): one forward
// real FFT per distinct exponent, products summed in Fourier space, one
// inverse FFT. The loss term c_k Σ_j K(k,j) c_j = c_k Σ_t c_t (k^p μ_q + k^q μ_p)
// needs only the moments μ_e = Σ_j j^e c_j. Same equation as DirectRhs.
//
// Active length: the transforms cover only masses 1..n, where n (a power of
// two, at most M) is at least twice the largest mass whose concentration
// exceeds `floor` times the largest concentration. Masses above hold nothing
// of consequence (the tails fall off exponentially, so what is skipped is of
// order floor^2) and n only grows, so the right-hand side stays a function of
// the state. Early on this makes the FFTs short and keeps the explicit time
// steps from being limited by the fast loss rates of empty large masses.
//
// Round-off: convolution by FFT carries an absolute error of about 1e-16 of
// the largest term, so concentrations far below the peak are only known to
// that absolute level (the integrator clamps the resulting tiny negatives).
// Plans use FFTW_ESTIMATE, so the arithmetic is the same run to run.
#pragma once
#include <fftw3.h>

#include <vector>

#include "analyze/smoluchowski/grid.h"
#include "analyze/smoluchowski/powers.h"

namespace coolgas::smoluchowski {

class FftRhs : public CoagulationRhs {
 public:
  static constexpr double kDefaultFloor = 1e-13;  // above the FFT noise (~1e-16 of the peak)

  FftRhs(const Kernel& kernel, std::int64_t M, double floor = kDefaultFloor);
  ~FftRhs() override;
  FftRhs(const FftRhs&) = delete;
  FftRhs& operator=(const FftRhs&) = delete;

  const MassGrid& grid() const override { return grid_; }
  void evaluate(const double* c, double* dcdt) override;
  // Masses 1..active_size() are currently evolved.
  std::size_t active_size() const { return active_; }

 private:
  struct Plans {
    fftw_plan forward = nullptr, inverse = nullptr;
  };
  void grow_active(const double* c);
  const Plans& plans_for(std::size_t length);
  void gain(const double* c, std::size_t length, double* out);
  void loss_moments(const double* c, std::vector<double>& mu) const;

  MassGrid grid_;
  KernelPowers powers_;
  double floor_;
  std::size_t active_ = 0;
  std::size_t max_length_;
  std::vector<Plans> plans_;        // indexed by log2 of the transform length
  double* real_ = nullptr;          // transform input/output, max_length_ reals
  fftw_complex* spectra_ = nullptr; // one spectrum per exponent, then the sum
};

}  // namespace coolgas::smoluchowski
