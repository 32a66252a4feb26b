#include "simulate/start/mixture_enskog.h"

#include <cmath>

namespace coolgas {

std::vector<std::vector<double>> enskog_pair_rates(const Scene& s, const std::vector<double>& T) {
  const Geometry g = s.geometry();
  const auto counts = s.species_counts();
  const std::size_t k = s.species.size();
  const double volume = g.box_measure(s.L);
  double xi = 0;  // Σ phi_k / σ_k
  for (std::size_t a = 0; a < k; ++a)
    xi += g.covered_fraction(double(counts[a]) * g.power(s.species[a].diameter), s.L) / s.species[a].diameter;
  std::vector<std::vector<double>> rate(k, std::vector<double>(k));
  for (std::size_t i = 0; i < k; ++i)
    for (std::size_t j = 0; j < k; ++j) {
      const double a = s.species[i].diameter, b = s.species[j].diameter;
      const double contact = g.mixture_contact_value(s.phi, xi, a, b);
      const double w = T[i] / s.species_mass(i) + T[j] / s.species_mass(j);
      rate[i][j] = g.enskog_pair_rate(double(counts[j]) / volume, contact, 0.5 * (a + b), w);
    }
  return rate;
}

double enskog_mean_rate(const Scene& s, double T) {
  const auto rate = enskog_pair_rates(s, std::vector<double>(s.species.size(), T));
  const auto counts = s.species_counts();
  double mean = 0;
  for (std::size_t i = 0; i < rate.size(); ++i)
    for (const double r : rate[i]) mean += double(counts[i]) / double(s.N) * r;
  return mean;
}

// The rates grow as √T.
double mixture_unit_time_temperature(const Scene& s) {
  const double at_one = enskog_mean_rate(s, 1.0);
  return 1.0 / (at_one * at_one);
}

}  // namespace coolgas
