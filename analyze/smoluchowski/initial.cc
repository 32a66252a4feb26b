#include "analyze/smoluchowski/initial.h"

#include <algorithm>
#include <cmath>

#include "common/error.h"
#include "common/tsv.h"

namespace coolgas::smoluchowski {

namespace {

// A log bin of the shared table shape has centre m = √(lo·hi) and dm = hi−lo+1,
// so lo solves lo (lo + dm − 1) = m².
std::int64_t bin_low_edge(double m, double dm) {
  return std::llround((-(dm - 1) + std::sqrt((dm - 1) * (dm - 1) + 4 * m * m)) / 2);
}

}  // namespace

std::vector<double> initial_masses(const Table& t, std::int64_t cutoff) {
  const std::size_t cm = t.column("m"), cn = t.column("N");
  const bool binned = std::find(t.columns.begin(), t.columns.end(), "dm") != t.columns.end();
  const std::size_t cd = binned ? t.column("dm") : 0;
  std::vector<double> c(2, 0.0);
  for (std::size_t r = 0; r < t.rows.size() && t.row_block[r] == 0; ++r) {
    const double m = t.rows[r][cm], N = t.rows[r][cn];
    const double dm = binned ? t.rows[r][cd] : 1;
    // Above the cut-off before any integer is made of it (a mass of 1e300 is
    // none llround can give) and before the vector grows for it: a bin's
    // centre and width are at most its upper edge.
    const auto above = [&](double mass) {
      return InputError(t.source + ": initial distribution row " + std::to_string(r + 1) + " holds mass " +
                        format_number(mass) + " above the cut-off M = " + std::to_string(cutoff) + "; raise --M");
    };
    if (m > double(cutoff) || dm > double(cutoff)) throw above(std::max(m, dm));
    const std::int64_t lo = binned ? bin_low_edge(m, dm) : std::llround(m);
    if (lo < 1 || (!binned && double(lo) != m) || N < 0 || dm < 1)
      throw InputError(t.source + ": initial distribution row " + std::to_string(r + 1) +
                       " needs an integer mass m >= 1 and N >= 0, got m = " + format_number(m) +
                       ", N = " + format_number(N));
    const auto hi = lo + std::llround(dm) - 1;
    if (hi > cutoff) throw above(double(hi));
    if (std::size_t(hi) + 1 > c.size()) c.resize(hi + 1, 0.0);
    for (auto k = lo; k <= hi; ++k) c[k] += N;
  }
  return c;
}

std::vector<double> initial_masses(const std::string& spec, std::int64_t cutoff) {
  if (spec == "mono") return {0.0, 1.0};
  return initial_masses(read_table(spec), cutoff);
}

std::vector<double> on_grid(const MassGrid& grid, const std::vector<double>& by_mass) {
  std::vector<double> c(grid.size(), 0.0);
  std::size_t k = 0;  // cell with pivot <= m
  for (std::size_t m = 1; m < by_mass.size(); ++m) {
    if (by_mass[m] == 0) continue;
    const double x = double(m);
    if (x > grid.mass.back())
      throw InputError("initial distribution holds mass " + std::to_string(m) + " above the cut-off M = " +
                       std::to_string(grid.cutoff()) + "; raise --M");
    while (k + 1 < grid.size() && grid.mass[k + 1] <= x) ++k;
    if (grid.mass[k] == x) {
      c[k] += by_mass[m];
    } else {  // between pivots k and k+1: share, conserving number and mass
      const double eta = (grid.mass[k + 1] - x) / (grid.mass[k + 1] - grid.mass[k]);
      c[k] += eta * by_mass[m];
      c[k + 1] += (1 - eta) * by_mass[m];
    }
  }
  return c;
}

}  // namespace coolgas::smoluchowski
