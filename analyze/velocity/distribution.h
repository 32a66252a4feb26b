// Velocity statistics of one frame, as in the paper (Pathak et al. 2014,
// Fig. 5): the distribution Φ(y) of velocity components scaled by v_rms, and
// the kurtosis of the speed distribution.
#pragma once
#include <cstdint>
#include <span>
#include <vector>

namespace coolgas {

// Moments of the speeds v = |v| of N particles.
struct SpeedMoments {
  std::int64_t particles = 0;
  double v_rms = 0;      // per component: sqrt(<v_x^2 + v_y^2 + v_z^2> / 3)
  double kappa = 0;      // <v^4>/<v^2>^2 - 5/3: zero for a Maxwellian (tests/physics/README.md)
  double kappa_err = 0;  // standard error of kappa (delta method, see distribution.cc)
};

// velocities: vx0 vy0 vz0 vx1 ... (3N numbers, N >= 2).
SpeedMoments speed_moments(std::span<const double> velocities);

// Histogram of y = v_alpha / v_rms over the three components pooled, on
// `bins` equal bins covering [-ymax, ymax]. Φ is normalised over all 3N
// components, so Σ Φ dy is the fraction inside the range (1 up to the tails).
class ComponentHistogram {
 public:
  ComponentHistogram(int bins, double ymax);

  void fill(std::span<const double> velocities, double v_rms);

  int bins() const { return static_cast<int>(count_.size()); }
  double width() const { return width_; }
  double center(int j) const { return double(2 * j + 1 - bins()) * ymax_ / bins(); }  // exact mirror images
  std::int64_t count(int j) const { return count_[j]; }
  std::int64_t samples() const { return samples_; }  // 3N, including those outside the range
  double phi(int j) const { return double(count_[j]) / (double(samples_) * width_); }

 private:
  double ymax_, width_;
  std::vector<std::int64_t> count_;
  std::int64_t samples_ = 0;
};

}  // namespace coolgas
