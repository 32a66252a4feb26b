// The mass-radius relation M ~ R_g^{d_f} of one frame's clusters: clusters
// binned by mass in the logarithmic bins of analyze/bins/log_bins.h; in each
// bin the means of ln m and ln R_g over its clusters; d_f from the straight
// line ln R_g = ln m / d_f + c through the bins whose mass lies in the fit
// window (unweighted least squares, analyze/curves/power_law.h; the error of
// d_f comes from the scatter of the bins about the line).
// Clusters that wrap around the box (no shape) and clusters of one point
// (R_g = 0) are left out of the bins and the fit.
#pragma once
#include <cstdint>
#include <vector>

#include "analyze/curves/fit_data.h"
#include "analyze/shape/cluster_shapes.h"

namespace coolgas {

struct MassRadiusBin {
  double m = 0;             // exp <ln m> over the bin's clusters
  std::int64_t dm = 0;      // integer masses in the bin
  std::int64_t clusters = 0;
  double Rg = 0, Rg_err = 0;  // exp <ln R_g>, and R_g times the standard error of <ln R_g>
  double asphericity = 0, prolateness = 0;  // means over the bin's clusters
};

struct MassRadius {
  std::vector<MassRadiusBin> bins;   // bins holding clusters, increasing mass
  double d_f = 0, d_f_err = 0;       // 0 when fewer than 3 bins lie in the window
  int fit_bins = 0;
  std::int64_t fitted_clusters = 0;
  double asphericity = 0, prolateness = 0;  // mass-weighted means over the fitted clusters
  double wrapping_fraction = 0;             // share of all mass in clusters that wrap
};

MassRadius mass_radius(const std::vector<ClusterShape>& clusters, int per_decade, const Window& fit);

}  // namespace coolgas
