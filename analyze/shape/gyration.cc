#include "analyze/shape/gyration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace coolgas {

Shape shape_of(const GyrationSums& g) {
  Shape out;
  out.mass = g.mass;
  if (g.mass < 2) return out;
  const double m = double(g.mass);
  const double c[3] = {g.s[0] / m, g.s[1] / m, g.s[2] / m};
  Eigen::Matrix3d G;
  G(0, 0) = g.ss[0] / m - c[0] * c[0];
  G(1, 1) = g.ss[1] / m - c[1] * c[1];
  G(2, 2) = g.ss[2] / m - c[2] * c[2];
  G(0, 1) = G(1, 0) = g.ss[3] / m - c[0] * c[1];
  G(0, 2) = G(2, 0) = g.ss[4] / m - c[0] * c[2];
  G(1, 2) = G(2, 1) = g.ss[5] / m - c[1] * c[2];
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(G, Eigen::EigenvaluesOnly);
  for (int i = 0; i < 3; ++i) out.lambda[i] = std::max(0.0, eig.eigenvalues()[i]);  // ascending; round-off below 0 is 0
  const double sum = out.lambda[0] + out.lambda[1] + out.lambda[2];
  out.Rg = std::sqrt(sum);
  if (sum <= 0) return out;
  const double mean = sum / 3;
  double dev2 = 0, prod = 1;
  for (double l : out.lambda) dev2 += (l - mean) * (l - mean), prod *= l - mean;
  out.asphericity = 1.5 * dev2 / (sum * sum);
  out.prolateness = 27 * prod / (sum * sum * sum);
  return out;
}

}  // namespace coolgas
