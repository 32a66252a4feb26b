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
constexpr int kMaxBinsPerSigma = 1000;
constexpr double kMaxRdfBins = 1e7;
constexpr double kDefaultRdfRange = 5;  // sigma: the structure of a dense fluid has faded by then

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
      series{"t", "L_t", "k_mean", "k_cut", "k_peak", "S_peak", "L_C", "L_v"}, correlation{"t", "r", "C", "C_v", "points"},
      rdf{"t", "r", "g", "g_err", "pairs"},
      rdf_series{"t", "g_contact", "g_contact_err", "kappa", "contact_pairs", "g_equilibrium"};
  switch (table) {
    case StructureTable::kSpectrum:
      return spectrum;
    case StructureTable::kSeries:
      return series;
    case StructureTable::kRdf:
      return rdf;
    case StructureTable::kRdfSeries:
      return rdf_series;
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

void check_rdf_options(double r_max, int bins_per_sigma, int contact_bins) {
  if (!(r_max >= 0 && std::isfinite(r_max)))
    throw InputError("--r-max must be a positive distance in sigma (0: min(5, L/2)), got " + format_number(r_max));
  if (bins_per_sigma < 1 || bins_per_sigma > kMaxBinsPerSigma)
    throw InputError("--bins-per-sigma must lie in [1, " + std::to_string(kMaxBinsPerSigma) + "], got " +
                     std::to_string(bins_per_sigma));
  if (contact_bins < 2 || contact_bins > bins_per_sigma)
    throw InputError("--contact-bins must lie in [2, --bins-per-sigma = " + std::to_string(bins_per_sigma) +
                     "] (the fit of g(sigma+) needs two bins, and at most one sigma), got " + std::to_string(contact_bins));
}

double rdf_range(double r_max, double L, int bins_per_sigma, int contact_bins) {
  const double r = r_max > 0 ? r_max : std::min(kDefaultRdfRange, L / 2);
  const double fit_end = 1.0 + double(contact_bins) / bins_per_sigma;
  if (r > L / 2)
    throw InputError("--r-max " + format_number(r) + " exceeds half the box side, L/2 = " + format_number(L / 2) +
                     " (distances are minimum images): give --r-max at most " + format_number(L / 2));
  if (std::floor(r * bins_per_sigma) < std::round(fit_end * bins_per_sigma))
    throw InputError("g(r) up to r = " + format_number(r) + (r_max > 0 ? "" : " (min(5, L/2))") +
                     " does not reach the end of the contact fit, sigma + --contact-bins/--bins-per-sigma = " +
                     format_number(fit_end) + (r_max > 0 ? ": raise --r-max" : ": the box is too small"));
  if (r * bins_per_sigma > kMaxRdfBins)
    throw InputError("--r-max " + format_number(r) + " at --bins-per-sigma " + std::to_string(bins_per_sigma) +
                     " makes more than 10^7 bins: lower either");
  return r;
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

TableBlock rdf_block(StructureTable table, PairDistances& pairs, double t, double L,
                     std::span<const double> positions, int contact_bins, Geometry g) {
  pairs.clear();
  pairs.add(L, positions);
  const ContactValue c = pairs.contact(contact_bins);
  const double equilibrium = g.contact_value(g.covered_fraction(double(positions.size() / 3), L));
  TableBlock b;
  if (table == StructureTable::kRdfSeries) {
    b.rows.push_back({t, c.g, c.err, c.kappa, c.pairs, equilibrium});
    return b;
  }
  b.comment = "t = " + format_number(t) + "; g_contact = " + format_number(c.g) + " +- " + format_number(c.err) +
              "; g_equilibrium = " + format_number(equilibrium);
  for (const RdfBin& r : pairs.bins()) b.rows.push_back({t, r.r, r.g, r.g_err, r.pairs});
  return b;
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
