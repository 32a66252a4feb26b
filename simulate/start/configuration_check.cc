#include "simulate/start/configuration_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "common/close_pairs.h"
#include "common/error.h"
#include "common/limits.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"

namespace coolgas {

namespace {

struct Spheres {
  const Particles& p;
  const AggregateState* a;
  const std::vector<double>* mixture;  // each particle's diameter in a mixture
  bool live(std::size_t i) const { return !a || a->id[i] >= 0; }
  double diameter(std::size_t i) const { return a ? a->diameter[i] : mixture ? (*mixture)[i] : 1.0; }
};

[[noreturn]] void refuse(const std::string& source, const std::string& what) {
  throw InputError(source + ": " + what);
}

std::string vec_text(const Vec3& r) {
  return "(" + format_number(r.x) + ", " + format_number(r.y) + ", " + format_number(r.z) + ")";
}

void check_sizes(const Spheres& s, const std::string& source) {
  const std::size_t n = s.p.size();
  if (n < 2 || double(n) >= 2147483648.0)
    refuse(source, "N = " + std::to_string(n) + " particles; allowed are 2 <= N < 2^31");
  if (s.p.v.size() != n || s.p.image.size() != n || (s.a && (s.a->diameter.size() != n || s.a->id.size() != n)) ||
      (s.mixture && s.mixture->size() != n))
    refuse(source, "positions, velocities and images hold different numbers of particles");
}

double largest_diameter(const Spheres& s, const std::string& source) {
  double d = s.mixture ? 0.0 : 1.0;
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if (!s.live(i)) continue;
    if (!(std::isfinite(s.diameter(i)) && (s.mixture ? s.diameter(i) > 0 : s.diameter(i) >= 1.0)))
      refuse(source, "particle " + std::to_string(i) + " has diameter " + format_number(s.diameter(i)) +
                         (s.mixture ? "; diameters are finite and > 0" : "; diameters are finite and >= 1"));
    d = std::max(d, s.diameter(i));
  }
  return d;
}

void check_box(double L, double width, const std::string& source, Geometry g) {
  if (!std::isfinite(L)) refuse(source, "box side L = " + format_number(L) + " is not a finite number");
  const std::string small = check_box_fits_grid(L, width);
  if (!small.empty()) refuse(source, small);
  if (g.grid_cells(L) > double(kMaxIndex32))
    refuse(source, "box side L = " + format_number(L) + " needs more than 2^31 grid cells; the limit is " +
                       g.grid_limit());
}

void check_values(const Spheres& s, const std::string& source) {
  const double L = s.p.L;
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if (!s.live(i)) continue;
    const Vec3& r = s.p.r[i];
    for (int d = 0; d < 3; ++d)
      if (!(r[d] >= 0 && r[d] < L))
        refuse(source, "particle " + std::to_string(i) + " is at " + vec_text(r) + ", outside the box [0, " +
                           format_number(L) + ")");
    if (!std::isfinite(dot(s.p.v[i], s.p.v[i])))
      refuse(source, "particle " + std::to_string(i) + " has velocity " + vec_text(s.p.v[i]) +
                         "; velocities are finite (and their squares too)");
    if (i < s.p.omega.size() && !std::isfinite(dot(s.p.omega[i], s.p.omega[i])))
      refuse(source, "particle " + std::to_string(i) + " has angular velocity " + vec_text(s.p.omega[i]) +
                         "; angular velocities are finite (and their squares too)");
  }
}

std::string six_digits(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}

double periodic_distance(const Vec3& a, const Vec3& b, double L) {
  Vec3 d{b.x - a.x, b.y - a.y, b.z - a.z};
  for (int k = 0; k < 3; ++k) d[k] -= L * std::round(d[k] / L);
  return std::sqrt(dot(d, d));
}

void refuse_pair(const Spheres& s, std::size_t i, std::size_t j, double r, const std::string& source) {
  const double contact = (s.diameter(i) + s.diameter(j)) / 2;
  refuse(source, "particles " + std::to_string(std::min(i, j)) + " and " + std::to_string(std::max(i, j)) +
                     " overlap: their centres are " + six_digits(r) + " apart, contact is at " +
                     format_number(contact));
}

bool overlapping(const Spheres& s, std::size_t i, std::size_t j, double* r) {
  *r = periodic_distance(s.p.r[i], s.p.r[j], s.p.L);
  return *r < (s.diameter(i) + s.diameter(j)) / 2 * (1 - kOverlapTolerance);
}

void check_overlaps(const Spheres& s, double width, const std::string& source, Geometry g) {
  std::vector<std::size_t> live;
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.live(i)) live.push_back(i);
  for_each_close_pair(
      live, [&](std::size_t i) { return s.p.r[i]; }, width, s.p.L, g, [&](std::size_t i, std::size_t j) {
        double r = 0;
        if (overlapping(s, i, j, &r)) refuse_pair(s, i, j, r, source);
      });
}

}  // namespace

void check_configuration(const Particles& p, const AggregateState* aggregates, const std::string& source,
                         Geometry g, const std::vector<double>* diameters) {
  const Spheres s{p, aggregates, diameters};
  check_sizes(s, source);
  const double width = largest_diameter(s, source);
  check_box(p.L, width, source, g);
  check_values(s, source);
  check_overlaps(s, width, source, g);
}

}  // namespace coolgas
