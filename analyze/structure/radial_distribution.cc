#include "analyze/structure/radial_distribution.h"

#include <cmath>
#include <numeric>

#include "common/close_pairs.h"

namespace coolgas {

PairDistances::PairDistances(Geometry g, double r_max, int bins_per_sigma)
    : g_(g), per_sigma_(bins_per_sigma), pairs_(std::size_t(std::floor(r_max * bins_per_sigma)), 0) {
  r_max_ = double(pairs_.size()) / per_sigma_;  // the last whole bin's edge
}

void PairDistances::add(double L, std::span<const double> positions) {
  const std::size_t n = positions.size() / 3;
  PairsWithin(positions, r_max_, L, g_).for_each([&](std::size_t, std::size_t, double r2) {
    const auto bin = std::size_t(std::sqrt(r2) * per_sigma_);
    if (bin < pairs_.size()) ++pairs_[bin];  // r just below r_max may round up to its edge
  });
  pair_density_ += 0.5 * double(n) * double(n - (n > 0)) / g_.box_measure(L);
}

void PairDistances::clear() {
  std::fill(pairs_.begin(), pairs_.end(), 0);
  pair_density_ = 0;
}

double PairDistances::ideal_pairs(std::size_t bin) const {
  const double lo = double(bin) / per_sigma_, hi = double(bin + 1) / per_sigma_;
  return pair_density_ * (g_.ball_measure(hi) - g_.ball_measure(lo));
}

std::vector<RdfBin> PairDistances::bins() const {
  std::vector<RdfBin> out(pairs_.size());
  for (std::size_t i = 0; i < pairs_.size(); ++i) {
    const double c = double(pairs_[i]), ideal = ideal_pairs(i);
    const double g = ideal > 0 ? c / ideal : 0.0;
    out[i] = {(double(i) + 0.5) / per_sigma_, g, c > 0 ? g / std::sqrt(c) : 0.0, c};
  }
  return out;
}

namespace {

// The Poisson log-likelihood of counts c_i of means E_i exp(a + b x_i).
double log_likelihood(const std::vector<double>& c, const std::vector<double>& E, const std::vector<double>& x,
                      double a, double b) {
  double l = 0;
  for (std::size_t i = 0; i < c.size(); ++i) l += c[i] * (a + b * x[i]) - E[i] * std::exp(a + b * x[i]);
  return l;
}

}  // namespace

ContactValue PairDistances::contact(int contact_bins) const {
  std::vector<double> c, E, x;  // counts, ideal counts, bin centre - sigma
  int nonempty = 0;
  for (int k = 0; k < contact_bins; ++k) {
    const auto i = std::size_t(per_sigma_ + k);
    if (i >= pairs_.size()) break;
    c.push_back(double(pairs_[i]));
    E.push_back(ideal_pairs(i));
    x.push_back((k + 0.5) / per_sigma_);
    nonempty += pairs_[i] > 0;
  }
  ContactValue v;
  const double C = std::accumulate(c.begin(), c.end(), 0.0), Etot = std::accumulate(E.begin(), E.end(), 0.0);
  v.pairs = C;
  if (C == 0 || Etot == 0) return v;
  if (nonempty < 2) {  // no slope to fit: their mean
    v.g = C / Etot;
    v.err = v.g / std::sqrt(C);
    return v;
  }
  // Newton's method on the concave log-likelihood, halving a step that
  // does not raise it; from the flat fit.
  double a = std::log(C / Etot), b = 0, s00 = 0, s01 = 0, s11 = 0;
  for (int it = 0; it < 200; ++it) {
    double g0 = 0, g1 = 0;
    s00 = s01 = s11 = 0;
    for (std::size_t i = 0; i < c.size(); ++i) {
      const double mu = E[i] * std::exp(a + b * x[i]);
      g0 += c[i] - mu, g1 += (c[i] - mu) * x[i];
      s00 += mu, s01 += mu * x[i], s11 += mu * x[i] * x[i];
    }
    const double det = s00 * s11 - s01 * s01;
    double da = (s11 * g0 - s01 * g1) / det, db = (s00 * g1 - s01 * g0) / det;
    const double l0 = log_likelihood(c, E, x, a, b);
    for (int h = 0; h < 60 && log_likelihood(c, E, x, a + da, b + db) < l0; ++h) da *= 0.5, db *= 0.5;
    a += da, b += db;
    if (std::abs(da) < 1e-14 * (1 + std::abs(a)) && std::abs(db) < 1e-12 * (1 + std::abs(b))) break;
  }
  v.g = std::exp(a);
  v.err = v.g * std::sqrt(s11 / (s00 * s11 - s01 * s01));  // (inverse Fisher information)_aa
  v.kappa = -b;
  return v;
}

}  // namespace coolgas
