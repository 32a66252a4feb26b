#include "analyze/structure/tool.h"

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "analyze/structure/frame_structure.h"
#include "analyze/structure/growing_length.h"
#include "common/trajectory/frame_reader.h"
#include "common/error.h"
#include "common/interrupt.h"
#include "common/tsv.h"

namespace coolgas {

namespace {

constexpr int kMaxGrid = 1024;  // 8 GB per grid beyond; no run of the paper needs it
constexpr int kMaxDirectShells = 8;

std::vector<std::string> columns(StructureTable t) {
  switch (t) {
    case StructureTable::kSpectrum:
      return {"t", "shell", "k", "S", "S_err", "modes", "x", "y"};
    case StructureTable::kSeries:
      return {"t", "L_t", "k_mean", "k_cut", "k_peak", "S_peak", "L_C", "L_v"};
    case StructureTable::kCorrelation:
      return {"t", "r", "C", "C_v", "points"};
  }
  return {};
}

const char* table_name(StructureTable t) {
  switch (t) {
    case StructureTable::kSpectrum:
      return "structure factor";
    case StructureTable::kSeries:
      return "growing length series";
    case StructureTable::kCorrelation:
      return "pair correlation";
  }
  return "";
}

void check(const StructureOptions& o) {
  if (o.grid != 0 && (o.grid < 8 || o.grid > kMaxGrid || o.grid % 2))
    throw InputError("--grid must be an even number of points per side in [8, " + std::to_string(kMaxGrid) +
                     "], got " + std::to_string(o.grid));
  if (!(o.peak_fraction > 0 && o.peak_fraction < 1))
    throw InputError("--peak-fraction must lie strictly between 0 and 1, got " + format_number(o.peak_fraction));
  if (o.direct_shells < 0 || o.direct_shells > kMaxDirectShells)
    throw InputError("--direct-shells must lie in [0, " + std::to_string(kMaxDirectShells) + "], got " +
                     std::to_string(o.direct_shells));
}

// The grid for box side L: the one asked for, or spacing about sigma.
int grid_points(const StructureOptions& o, double L) {
  if (o.grid) return o.grid;
  const int n = 2 * int(std::floor(L / 2));
  if (n < 8)
    throw InputError("box side L = " + format_number(L) + " is too small for coolgas-structure (needs L >= 8, or --grid)");
  return std::min(n, kMaxGrid);
}

Provenance provenance(const Trajectory& traj, const StructureOptions& o, int n, double L) {
  Provenance p = traj.provenance();
  p.emplace_back("table", table_name(o.table));
  p.emplace_back("density", traj.aggregates() ? "aggregates weighted by their mass (ballistic aggregation): S of "
                                                 "their particles, each at its aggregate's centre"
                                               : "particles, unit weight");
  p.emplace_back("grid", std::to_string(n) + "^3 points, spacing " + format_number(L / n) + " sigma");
  p.emplace_back("assignment", "cloud in cell; S = s + (|rho_grid|^2/M - s C1)/W^2 (Jing 2005, ApJ 620, 559)");
  p.emplace_back("shells", "|k| L/(2 pi) rounded, 1 .. grid/4 (k up to half the grid's Nyquist wave number)");
  p.emplace_back("peak_fraction", format_number(o.peak_fraction));
  p.emplace_back("L_t", "2 pi / <k>, first moment of S over the low-k peak (cut: S - s <= peak_fraction (S_max - s))");
  p.emplace_back("direct_shells", std::to_string(o.direct_shells));
  for (double t : o.times) p.emplace_back("time", format_number(t));
  return p;
}

// "# t = ...; L_t = ...; direct sum: shell 1 S = ... (grid ...)": the check
// of the grid estimate against the exact sum, in each block's comment.
std::string block_comment(const Frame& f, const PeakLength& len, const std::vector<Shell>& shells,
                          const std::vector<double>& direct) {
  std::string s = "t = " + format_number(f.time) + "; L_t = " + format_number(len.L) + "; k_cut = " +
                  format_number(len.k_cut);
  for (std::size_t i = 0; i < direct.size(); ++i) {
    const auto grid = std::find_if(shells.begin(), shells.end(), [&](const Shell& sh) { return sh.index == int(i) + 1; });
    if (grid == shells.end()) continue;
    s += "; shell " + std::to_string(i + 1) + ": S_direct = " + format_number(direct[i]) + ", S = " + format_number(grid->S);
  }
  return s;
}

void write_spectrum(TsvWriter& out, const Frame& f, const PeakLength& len, const std::vector<Shell>& shells,
                    const std::vector<double>& direct) {
  out.block(block_comment(f, len, shells, direct));
  for (const Shell& s : shells)
    out.row({f.time, double(s.index), s.k, s.S, s.S_err, s.modes, s.k * len.L,
             len.L > 0 ? s.S / (len.L * len.L * len.L) : 0.0});
}

void write_correlation(TsvWriter& out, double t, const std::vector<CorrelationBin>& c,
                       const std::vector<CorrelationBin>& cv) {
  out.block("t = " + format_number(t) + "; L_C = " + format_number(first_zero(c)) + "; L_v = " +
            format_number(first_zero(cv)));
  for (std::size_t b = 0; b < c.size(); ++b) out.row({t, c[b].r, c[b].C, cv[b].C, c[b].points});
}

std::span<const double> frame_weights(const Trajectory& traj, const Frame& f) {
  return traj.aggregates() ? std::span<const double>(f.mass) : std::span<const double>();
}

}  // namespace

void run_structure(const StructureOptions& opt, std::ostream& final_out) {
  check(opt);
  const bool velocity = opt.table != StructureTable::kSpectrum;
  Trajectory traj(opt.input, velocity ? (kPosition | kVelocity) : kPosition);
  const std::vector<std::size_t> dumps = traj.dumps_nearest(opt.times, opt.exact_time);
  if (dumps.empty()) throw InputError(opt.input + ": the trajectory holds no dumps");
  Frame frame;
  traj.read(dumps.front(), frame);
  const int n = grid_points(opt, frame.L);
  std::ostringstream os;  // written only when every dump has been read
  TsvWriter out(os, "coolgas-structure", provenance(traj, opt, n, frame.L), columns(opt.table));
  FrameStructure fs(n);
  for (std::size_t i = 0; i < dumps.size(); ++i) {
    throw_if_interrupted(i, dumps.size(), "dumps");
    if (i > 0) traj.read(dumps[i], frame);
    const auto weights = frame_weights(traj, frame);
    const Weights w = weights_of(weights, frame.particles());
    const std::vector<Shell> shells = fs.spectrum(frame.L, frame.position, weights);
    const PeakLength len = peak_length(shells, w.shot, opt.peak_fraction);
    if (opt.table == StructureTable::kSpectrum) {
      write_spectrum(out, frame, len, shells,
                     direct_structure_factor(frame.L, frame.position, weights, opt.direct_shells));
      continue;
    }
    const auto c = fs.density_correlation(frame.L);
    const auto cv = fs.momentum_correlation(frame.L, frame.position, frame.velocity, weights);
    if (opt.table == StructureTable::kSeries)
      out.row({frame.time, len.L, len.k_mean, len.k_cut, len.k_peak, len.S_peak, first_zero(c), first_zero(cv)});
    else
      write_correlation(out, frame.time, c, cv);
  }
  final_out << os.str();
}

}  // namespace coolgas
