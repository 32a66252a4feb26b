#include "simulate/start/configuration_check.h"

#include "common/limits.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "common/error.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"

namespace coolgas {

namespace {

struct Spheres {
  const Particles& p;
  const AggregateState* a;
  bool live(std::size_t i) const { return !a || a->id[i] >= 0; }
  double diameter(std::size_t i) const { return a ? a->diameter[i] : 1.0; }
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
  if (s.p.v.size() != n || s.p.image.size() != n || (s.a && (s.a->diameter.size() != n || s.a->id.size() != n)))
    refuse(source, "positions, velocities and images hold different numbers of particles");
}

double largest_diameter(const Spheres& s, const std::string& source) {
  double d = 1.0;
  for (std::size_t i = 0; i < s.p.size(); ++i) {
    if (!s.live(i)) continue;
    if (!(std::isfinite(s.diameter(i)) && s.diameter(i) >= 1.0))
      refuse(source, "particle " + std::to_string(i) + " has diameter " + format_number(s.diameter(i)) +
                         "; diameters are finite and >= 1");
    d = std::max(d, s.diameter(i));
  }
  return d;
}

void check_box(double L, double width, const std::string& source, int dimension) {
  if (!std::isfinite(L)) refuse(source, "box side L = " + format_number(L) + " is not a finite number");
  const std::string small = check_box_fits_grid(L, width);
  if (!small.empty()) refuse(source, small);
  if (std::pow(std::floor(L), dimension) > double(kMaxIndex32))
    refuse(source, "box side L = " + format_number(L) + " needs more than 2^31 grid cells; the limit is L < " +
                       (dimension == 3 ? std::to_string(max_grid_side() + 1) : "2^(31/" + std::to_string(dimension) + ")"));
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

// Particles sorted by cell: cells[c] .. cells[c + 1] index into `order`.
struct CellIndex {
  int n, ny, nz;  // cells along x, y and z (ny = 1 for rods, nz = 1 for disks and rods)
  std::vector<std::size_t> start, order;
};

CellIndex sort_into_cells(const Spheres& s, double width, int dimension) {
  // Cells at least as wide as the widest sphere, and not many more than
  // particles (in 1D one row of about as many cells as rods).
  const double count = double(s.p.size());
  const double most = dimension == 3 ? std::ceil(std::cbrt(count)) : (dimension == 2 ? std::ceil(std::sqrt(count)) : count);
  const double per_side = std::min(std::floor(s.p.L / width), most + 1);
  const int n = int(per_side);
  CellIndex g{n, dimension >= 2 ? n : 1, dimension == 3 ? n : 1, {}, {}};
  const double w = s.p.L / g.n;
  auto cell = [&](std::size_t i) {
    auto c = [&](double u, int cells) { return std::min(int(u / w), cells - 1); };
    const Vec3& r = s.p.r[i];
    return (std::size_t(c(r.z, g.nz)) * std::size_t(g.ny) + std::size_t(c(r.y, g.ny))) * std::size_t(g.n) +
           std::size_t(c(r.x, g.n));
  };
  g.start.assign(std::size_t(g.n) * std::size_t(g.ny) * std::size_t(g.nz) + 1, 0);
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.live(i)) ++g.start[cell(i) + 1];
  for (std::size_t c = 1; c < g.start.size(); ++c) g.start[c] += g.start[c - 1];
  g.order.resize(g.start.back());
  std::vector<std::size_t> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < s.p.size(); ++i)
    if (s.live(i)) g.order[fill[cell(i)]++] = i;
  return g;
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

void check_overlaps(const Spheres& s, double width, const std::string& source, int dimension) {
  const CellIndex g = sort_into_cells(s, width, dimension);
  const int n = g.n;  // >= 3 (check_box), so the 27 neighbour cells are distinct (3 x 3 x 1 in 2D, 3 in 1D)
  for (int cz = 0; cz < g.nz; ++cz)
    for (int cy = 0; cy < g.ny; ++cy)
      for (int cx = 0; cx < n; ++cx) {
        const std::size_t c = (std::size_t(cz) * std::size_t(g.ny) + std::size_t(cy)) * std::size_t(n) + std::size_t(cx);
        for (int o = 0; o < 27; ++o) {
          const int oy = o / 3 % 3 - 1, oz = o / 9 - 1;
          if ((g.ny == 1 && oy != 0) || (g.nz == 1 && oz != 0)) continue;  // one cell across: once
          const int nx = (cx + o % 3 - 1 + n) % n, ny = (cy + oy + g.ny) % g.ny, nz = (cz + oz + g.nz) % g.nz;
          const std::size_t b = (std::size_t(nz) * std::size_t(g.ny) + std::size_t(ny)) * std::size_t(n) + std::size_t(nx);
          for (std::size_t a = g.start[c]; a < g.start[c + 1]; ++a)
            for (std::size_t k = g.start[b]; k < g.start[b + 1]; ++k) {
              const std::size_t i = g.order[a], j = g.order[k];
              double r = 0;
              if (i < j && overlapping(s, i, j, &r)) refuse_pair(s, i, j, r, source);
            }
        }
      }
}

}  // namespace

void check_configuration(const Particles& p, const AggregateState* aggregates, const std::string& source,
                         int dimension) {
  const Spheres s{p, aggregates};
  check_sizes(s, source);
  const double width = largest_diameter(s, source);
  check_box(p.L, width, source, dimension);
  check_values(s, source);
  check_overlaps(s, width, source, dimension);
}

}  // namespace coolgas
