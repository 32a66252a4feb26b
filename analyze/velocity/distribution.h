// Velocity statistics of one frame, as in the paper (Pathak et al. 2014,
// Fig. 5): the distribution Φ(y) of velocity components scaled by v_rms, and
// the kurtosis of the speed distribution.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "common/geometry.h"

namespace coolgas {

// Moments of the speeds v = |v| of N particles in d dimensions.
struct SpeedMoments {
  std::int64_t particles = 0;
  double v_rms = 0;      // per component: sqrt(<v_x^2 + ... > / d)
  double kappa = 0;      // <v^4>/<v^2>^2 - (d+2)/d: zero for a Maxwellian (tests/physics/README.md)
  double kappa_err = 0;  // standard error of kappa (delta method, see distribution.cc)
};

// The Maxwellian's <v^4>/<v^2>^2 in d dimensions: (d+2)/d (5/3 in 3D, 2 in
// 2D, 3 in 1D: a Gaussian's kurtosis), since v^2/T is chi-squared with d
// degrees of freedom.
inline double maxwellian_speed_ratio(int dimension) { return double(dimension + 2) / double(dimension); }

// velocities: vx0 vy0 vz0 vx1 ... (3N numbers, N >= 2; in 2D, dimension = 2,
// every vz is 0; in 1D, every vy and vz).
SpeedMoments speed_moments(std::span<const double> velocities, Geometry g);

// Histogram of y = v_alpha / v_rms over the d components pooled, on `bins`
// equal bins covering [-ymax, ymax]. Φ is normalised over all dN
// components, so Σ Φ dy is the fraction inside the range (1 up to the tails).
// Each component of a Maxwellian is Gaussian in every d: Φ(y) = e^{-y²/2}/√(2π).
class ComponentHistogram {
 public:
  ComponentHistogram(int bins, double ymax);

  // velocities as in speed_moments(); only the first `dimension` components
  // of each particle are counted.
  void fill(std::span<const double> velocities, double v_rms, Geometry g);

  int bins() const { return static_cast<int>(count_.size()); }
  double width() const { return width_; }
  double center(int j) const { return double(2 * j + 1 - bins()) * ymax_ / bins(); }  // exact mirror images
  std::int64_t count(int j) const { return count_[j]; }
  std::int64_t samples() const { return samples_; }  // dN, including those outside the range
  double phi(int j) const { return double(count_[j]) / (double(samples_) * width_); }

 private:
  double ymax_, width_;
  std::vector<std::int64_t> count_;
  std::int64_t samples_ = 0;
};

}  // namespace coolgas
