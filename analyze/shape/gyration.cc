#include "analyze/shape/gyration.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace coolgas {

namespace {

// The eigenvalues (ascending, round-off below 0 set to 0) of the d x d
// leading block of the gyration tensor G (3 x 3).
template <int D>
void eigenvalues(const Eigen::Matrix3d& G, std::array<double, 3>& lambda) {
  using Matrix = Eigen::Matrix<double, D, D>;
  const Eigen::SelfAdjointEigenSolver<Matrix> eig(Matrix(G.topLeftCorner<D, D>()), Eigen::EigenvaluesOnly);
  for (int i = 0; i < D; ++i) lambda[i] = std::max(0.0, eig.eigenvalues()[i]);
}

}  // namespace

Shape shape_of(const GyrationSums& g, Geometry geometry) {
  const int dimension = geometry.d();
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
  if (dimension == 3) eigenvalues<3>(G, out.lambda);
  else if (dimension == 2) eigenvalues<2>(G, out.lambda);
  else out.lambda[0] = std::max(0.0, G(0, 0));
  const double sum = out.lambda[0] + out.lambda[1] + out.lambda[2];
  out.Rg = std::sqrt(sum);
  if (sum <= 0 || dimension == 1) return out;  // 1D: R_g is all there is
  const double mean = sum / dimension;
  double dev2 = 0, prod = 1;
  for (int i = 0; i < dimension; ++i) {
    const double l = out.lambda[std::size_t(i)];
    dev2 += (l - mean) * (l - mean), prod *= l - mean;
  }
  out.asphericity = double(dimension) / double(dimension - 1) * dev2 / (sum * sum);
  if (dimension == 3) out.prolateness = 27 * prod / (sum * sum * sum);
  return out;
}

}  // namespace coolgas
