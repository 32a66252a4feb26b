#include "analyze/structure/frame_structure.h"

#include <algorithm>


namespace coolgas {

std::vector<Shell> FrameStructure::spectrum(double L, std::span<const double> positions,
                                            std::span<const double> weights) {
  grid_.clear();
  cic_.assign(grid_, L, positions, weights);
  grid_.forward();
  return shell_average(grid_, L, weights_of(weights, positions.size() / 3));
}

std::vector<CorrelationBin> FrameStructure::density_correlation(double L) {
  std::fill(power_.begin(), power_.end(), 0.0);
  add_power(grid_, power_);
  return radial_correlation(grid_, L, power_);
}

std::vector<CorrelationBin> FrameStructure::momentum_correlation(double L, std::span<const double> positions,
                                                                 std::span<const double> velocities,
                                                                 std::span<const double> weights) {
  std::fill(power_.begin(), power_.end(), 0.0);
  const std::size_t count = positions.size() / 3;
  component_.resize(count);
  for (int a = 0; a < grid_.dimension(); ++a) {
    for (std::size_t j = 0; j < count; ++j) component_[j] = (weights.empty() ? 1.0 : weights[j]) * velocities[3 * j + a];
    grid_.clear();
    cic_.assign(grid_, L, positions, component_);
    grid_.forward();
    add_power(grid_, power_);
  }
  return radial_correlation(grid_, L, power_);
}

}  // namespace coolgas
