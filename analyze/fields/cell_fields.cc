#include "analyze/fields/cell_fields.h"

#include <algorithm>
#include <cmath>

namespace coolgas {

int CellFields::occupied() const {
  return int(std::count_if(count.begin(), count.end(), [](double x) { return x > 0; }));
}

namespace {

// The cell index along one axis of a coordinate wrapped into [0, L).
int cell_along(double x, double L, int n) {
  double w = std::fmod(x, L);
  if (w < 0) w += L;
  return std::min(n - 1, int(w / L * n));
}

// Cell c's neighbour one step along axis a (periodic), `step` = +1 or -1.
std::int64_t neighbour(const CellFields& f, std::int64_t c, int a, int step) {
  std::int64_t stride = 1;
  for (int b = 0; b < a; ++b) stride *= f.n;
  const int i = int((c / stride) % f.n), j = (i + step + f.n) % f.n;
  return c + (j - i) * stride;
}

// d u_b / d x_a at cell c, central differences; 0 along an axis beyond d.
double derivative(const CellFields& f, std::int64_t c, int a, int b) {
  if (a >= f.g.d()) return 0;
  return (f.flow(neighbour(f, c, a, 1), b) - f.flow(neighbour(f, c, a, -1), b)) / (2 * f.cell_side());
}

}  // namespace

double cell_temperature(const CellFields& f, std::int64_t c) {
  if (f.count[c] < 2) return 0;
  double flow2 = 0;  // |p_c|^2 / M_c
  for (int a = 0; a < 3; ++a) flow2 += f.flow(c, a) * f.momentum[3 * c + a];
  return 2 * (f.kinetic[c] - flow2 / 2) / (f.g.d() * (f.count[c] - 1));
}

std::array<double, 3> cell_vorticity(const CellFields& f, std::int64_t c) {
  return {derivative(f, c, 1, 2) - derivative(f, c, 2, 1), derivative(f, c, 2, 0) - derivative(f, c, 0, 2),
          derivative(f, c, 0, 1) - derivative(f, c, 1, 0)};
}

CellFields cell_fields(int n, Geometry g, double L, std::span<const double> positions,
                       std::span<const double> velocities, std::span<const double> masses) {
  CellFields f;
  f.n = n, f.g = g, f.L = L;
  const std::int64_t cells = std::int64_t(g.power(n));
  f.count.assign(cells, 0), f.mass.assign(cells, 0), f.kinetic.assign(cells, 0), f.momentum.assign(3 * cells, 0);
  const std::size_t np = positions.size() / 3;
  f.particles = std::int64_t(np);
  // The centre of mass's velocity, taken off every particle.
  double m_total = 0, p_total[3] = {0, 0, 0};
  for (std::size_t j = 0; j < np; ++j) {
    const double m = masses.empty() ? 1.0 : masses[j];
    m_total += m;
    for (int a = 0; a < 3; ++a) p_total[a] += m * velocities[3 * j + a];
  }
  f.total_mass = m_total;
  for (std::size_t j = 0; j < np; ++j) {
    const double m = masses.empty() ? 1.0 : masses[j];
    std::int64_t c = 0, stride = 1;
    for (int a = 0; a < g.d(); ++a, stride *= n) c += stride * cell_along(positions[3 * j + a], L, n);
    f.count[c] += 1, f.mass[c] += m;
    for (int a = 0; a < 3; ++a) {
      const double v = velocities[3 * j + a] - p_total[a] / m_total;
      f.momentum[3 * c + a] += m * v;
      f.kinetic[c] += 0.5 * m * v * v;
    }
  }
  return f;
}

FieldEnergies field_energies(const CellFields& f) {
  FieldEnergies e;
  double sum_count = 0, sum_count2 = 0;
  for (std::int64_t c = 0; c < f.cells(); ++c) {
    e.kinetic += f.kinetic[c];
    if (f.mass[c] > 0) {
      double p2 = 0;
      for (int a = 0; a < 3; ++a) p2 += f.momentum[3 * c + a] * f.momentum[3 * c + a];
      e.flow += p2 / (2 * f.mass[c]);
    }
    sum_count += f.count[c], sum_count2 += f.count[c] * f.count[c];
  }
  e.thermal = e.kinetic - e.flow;
  const int occupied = f.occupied();
  const double dof = double(f.g.d()) * double(f.particles - occupied);
  e.temperature = dof > 0 ? 2 * e.thermal / dof : 0;
  e.flow_noise = 0.5 * f.g.d() * e.temperature * (occupied - 1);
  const double mean = sum_count / double(f.cells());
  e.density_variance = (sum_count2 / double(f.cells()) - mean * mean) / mean;
  const double M = f.total_mass;
  e.kinetic /= M, e.flow /= M, e.thermal /= M, e.flow_noise /= M;
  return e;
}

}  // namespace coolgas
