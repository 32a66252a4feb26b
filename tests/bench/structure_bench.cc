// Speed of coolgas-structure on the paper's largest system: N = 8e6 particles
// at phi = 0.208 (L = 272.1) on its default 272^3 grid, one frame, file
// reading excluded (cluster_bench measures that), FFTW_ESTIMATE plans made
// once (the tool reuses them from dump to dump):
//   1. S(k) and L_t: cloud-in-cell assignment, one r2c FFT, shell average;
//   2. the exact sum over particles for the lowest shell (the default check);
//   3. the series' extra work: C(r) of the density (one c2r FFT) and C_v(r)
//      of the momentum field (three assignments, three r2c, one c2r).
// Uniformly random centres in id order, the worst case for the assignment's
// memory access. Prints medians of 5 repeats, wall-clock and thread CPU time.
//
// `structure_bench fft N`: one r2c transform of an N^3 grid alone (median of
// 3), the longest call coolgas-structure makes that a signal cannot stop;
// N = 1024, the --grid limit, needs 8.6 GB.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "analyze/structure/cloud_in_cell.h"
#include "analyze/fourier/fourier_grid.h"
#include "analyze/structure/frame_structure.h"
#include "analyze/structure/growing_length.h"
#include "common/random.h"
#include "tests/bench/median_timing.h"

namespace {

constexpr std::int64_t kN = 8'000'000;
constexpr double kPhi = 0.208;
const double kL = std::cbrt(kN * M_PI / (6 * kPhi));

using coolgas::bench::median_time;
using coolgas::bench::Timing;
using coolgas::bench::wall_seconds;

void report(const char* what, const Timing& t) {
  std::printf("%-58s %7.0f ms wall, %7.0f ms cpu\n", what, 1e3 * t.wall, 1e3 * t.cpu);
}

// One transform of an n^3 grid of random numbers: the bound a signal may wait.
int time_one_transform(int n) {
  coolgas::FourierGrid g(n, coolgas::Geometry(3));
  coolgas::Random rng(1);
  const std::int64_t reals = std::int64_t(g.padded()) * n * n;
  for (std::int64_t i = 0; i < reals; ++i) g.real()[i] = rng.uniform();
  char what[64];
  std::snprintf(what, sizeof what, "one r2c FFT of a %d^3 grid (FFTW_ESTIMATE)", n);
  report(what, median_time(3, [&] { g.forward(); }));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 3 && std::string(argv[1]) == "fft") return time_one_transform(std::atoi(argv[2]));
  const int n = 2 * int(std::floor(kL / 2));
  std::printf("N = %lld, phi = %.3f, L = %.2f, grid %d^3\n", (long long)kN, kPhi, kL, n);
  coolgas::Random rng(1);
  std::vector<double> pos(3 * kN), vel(3 * kN);
  for (double& x : pos) x = kL * rng.uniform();
  for (double& v : vel) v = rng.normal();
  const double t0 = wall_seconds();
  coolgas::FrameStructure fs(n, coolgas::Geometry(3));
  std::printf("plans (FFTW_ESTIMATE) and grid allocation: %.0f ms\n", 1e3 * (wall_seconds() - t0));
  coolgas::PeakLength len;
  report("S(k) + L_t (assignment, r2c FFT, shells)", median_time(5, [&] {
           len = coolgas::peak_length(fs.spectrum(kL, pos, {}), 1, 0.1);
         }));
  {  // where the time goes
    coolgas::FourierGrid g(n, coolgas::Geometry(3));
    coolgas::CloudInCell cic;
    report("  of which: clear + cloud-in-cell assignment (sort included)", median_time(3, [&] {
             g.clear();
             cic.assign(g, kL, pos);
           }));
    report("  of which: r2c FFT", median_time(3, [&] { g.forward(); }));
    g.clear();
    cic.assign(g, kL, pos);
    g.forward();
    report("  of which: shell average", median_time(3, [&] { coolgas::shell_average(g, kL, {double(kN), 1}); }));
  }
  std::vector<double> direct;
  report("exact sum over particles, shell 1 (9 modes)", median_time(3, [&] {
           direct = coolgas::direct_structure_factor(kL, pos, {}, 1, coolgas::Geometry(3));
         }));
  report("series extra: C(r) of the density", median_time(3, [&] { fs.density_correlation(kL); }));
  report("series extra: C_v(r) of the momentum field", median_time(3, [&] {
           fs.momentum_correlation(kL, pos, vel, {});
         }));
  std::printf("(L_t = %.3f, S(shell 1) exact = %.4f)\n", len.L, direct[0]);
  return 0;
}
