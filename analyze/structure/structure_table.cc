#include "analyze/structure/structure_table.h"

#include <algorithm>
#include <cmath>

#include "analyze/structure/growing_length.h"
#include "common/error.h"
#include "common/memory.h"

namespace coolgas {

namespace {

constexpr int kMaxGrid = 1024;  // 8 GB per grid beyond; no run of the paper needs it
constexpr int kMaxDirectShells = 8;

// "t = ...; L_t = ...; k_cut = ...; shell 1: S_direct = ..., S = ...": the
// check of the grid estimate against the exact sum, in each block's comment.
std::string spectrum_comment(double t, const PeakLength& len, const std::vector<Shell>& shells,
                             const std::vector<double>& direct) {
  std::string s = "t = " + format_number(t) + "; L_t = " + format_number(len.L) + "; k_cut = " +
                  format_number(len.k_cut);
  for (std::size_t i = 0; i < direct.size(); ++i) {
    const auto grid = std::find_if(shells.begin(), shells.end(), [&](const Shell& sh) { return sh.index == int(i) + 1; });
    if (grid == shells.end()) continue;
    s += "; shell " + std::to_string(i + 1) + ": S_direct = " + format_number(direct[i]) + ", S = " + format_number(grid->S);
  }
  return s;
}

}  // namespace

const std::vector<std::string>& structure_columns(StructureTable table) {
  static const std::vector<std::string> spectrum{"t", "shell", "k", "S", "S_err", "modes", "x", "y"},
      series{"t", "L_t", "k_mean", "k_cut", "k_peak", "S_peak", "L_C", "L_v"}, correlation{"t", "r", "C", "C_v", "points"};
  switch (table) {
    case StructureTable::kSpectrum:
      return spectrum;
    case StructureTable::kSeries:
      return series;
    case StructureTable::kCorrelation:
      break;
  }
  return correlation;
}

void check_structure_options(int grid, double peak_fraction, int direct_shells) {
  if (grid != 0 && (grid < 8 || grid > kMaxGrid || grid % 2))
    throw InputError("--grid must be an even number of points per side in [8, " + std::to_string(kMaxGrid) +
                     "], got " + std::to_string(grid));
  if (!(peak_fraction > 0 && peak_fraction < 1))
    throw InputError("--peak-fraction must lie strictly between 0 and 1, got " + format_number(peak_fraction));
  if (direct_shells < 0 || direct_shells > kMaxDirectShells)
    throw InputError("--direct-shells must lie in [0, " + std::to_string(kMaxDirectShells) + "], got " +
                     std::to_string(direct_shells));
}

double structure_grid_bytes(int n, Geometry g) {
  const double rows = double(g.along(1, n)) * double(g.along(2, n));  // rows along x: n^(d-1)
  return (double(2 * (n / 2 + 1)) + double(n / 2 + 1)) * rows * sizeof(double);
}

int structure_grid_points(int grid, double L, Geometry g, double memory_bytes) {
  int n = grid;
  if (!n) {
    // Compared as a double: a box of 1e300 makes no int.
    if (!(L >= 8)) throw InputError("box side L = " + format_number(L) + " is too small for coolgas-structure (needs L >= 8, or --grid)");
    n = L >= kMaxGrid ? kMaxGrid : 2 * int(std::floor(L / 2));
  }
  const double need = structure_grid_bytes(n, g);
  if (need <= memory_bytes) return n;
  int fits = n;
  while (fits >= 8 && structure_grid_bytes(fits, g) > memory_bytes) fits -= 2;
  throw InputError("--grid " + std::to_string(n) + (grid ? "" : " (the default for L = " + format_number(L) + ")") +
                   " would need " + bytes_text(need) + " for its density grid; the memory available is " +
                   bytes_text(memory_bytes) + ": --grid at most " + (fits >= 8 ? std::to_string(fits) : "none (8 is the least)"));
}

TableBlock structure_block(StructureTable table, FrameStructure& fs, double t, double L,
                           std::span<const double> positions, std::span<const double> velocities,
                           std::span<const double> weights, double peak_fraction, int direct_shells) {
  const Weights w = weights_of(weights, positions.size() / 3);
  const std::vector<Shell> shells = fs.spectrum(L, positions, weights);
  const PeakLength len = peak_length(shells, w.shot, peak_fraction);
  TableBlock b;
  if (table == StructureTable::kSpectrum) {
    const Geometry g = fs.geometry();
    b.comment = spectrum_comment(t, len, shells, direct_structure_factor(L, positions, weights, direct_shells, g));
    const double volume = g.box_measure(len.L);  // L_t^d
    for (const Shell& s : shells)
      b.rows.push_back({t, double(s.index), s.k, s.S, s.S_err, s.modes, s.k * len.L, len.L > 0 ? s.S / volume : 0.0});
    return b;
  }
  const auto c = fs.density_correlation(L);
  const auto cv = fs.momentum_correlation(L, positions, velocities, weights);
  if (table == StructureTable::kSeries) {
    b.rows.push_back({t, len.L, len.k_mean, len.k_cut, len.k_peak, len.S_peak, first_zero(c), first_zero(cv)});
    return b;
  }
  b.comment = "t = " + format_number(t) + "; L_C = " + format_number(first_zero(c)) + "; L_v = " +
              format_number(first_zero(cv));
  for (std::size_t i = 0; i < c.size(); ++i) b.rows.push_back({t, c[i].r, c[i].C, cv[i].C, c[i].points});
  return b;
}

}  // namespace coolgas
