// The speed target of coolgas-smoluchowski: the paper's kernel Eq. (4),
// M = 2^16, monodisperse start, until the mean mass reaches 1000 (t ≈ 86.5 in
// the ½-gain convention), on one core. Prints wall time, steps, mass
// conservation and the final mean mass for each method setting; the README
// quotes these figures. Usage: smoluchowski_bench [repeats, default 3]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "analyze/smoluchowski/run.h"

namespace {

using namespace coolgas::smoluchowski;

struct Case {
  const char* label;
  Method method;
  double rtol, atol, ratio;
};

void measure(const Case& c, int repeats) {
  RunOptions o;
  o.kernel = "ballistic";
  o.method.method = c.method;
  o.method.M = 1 << 16;
  o.method.grid_ratio = c.ratio;
  o.integrator.rtol = c.rtol;
  o.integrator.atol = c.atol;
  o.until_mean_mass = 1000;
  double best = 1e300;
  RunSummary s;
  for (int r = 0; r < repeats; ++r) {
    std::ostringstream out, warn;
    const auto start = std::chrono::steady_clock::now();
    s = run(o, out, warn);
    best = std::min(best, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  std::printf("%-40s %9.3f %8ld %10ld %12.3e %14.10g %10.3f\n", c.label, best, s.steps, s.evaluations,
              s.leaked_fraction, s.final_moments.mean(), s.t);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  std::printf("Smoluchowski, kernel Eq. (4), M = 65536, monodisperse, until M_avg = 1000 (best of %d)\n", repeats);
  std::printf("%-40s %9s %8s %10s %12s %14s %10s\n", "method", "wall_s", "steps", "rhs_evals", "mass_lost",
              "mean_mass", "t_half");
  for (const Case& c : {Case{"fft rkck rtol 1e-6 atol 1e-12", Method::Fft, 1e-6, 1e-12, 1},
                        Case{"fft rkck rtol 1e-8 atol 1e-14 (default)", Method::Fft, 1e-8, 1e-14, 1},
                        Case{"fft rkck rtol 1e-10 atol 1e-16", Method::Fft, 1e-10, 1e-16, 1},
                        Case{"geometric r=1.05 rtol 1e-8", Method::Geometric, 1e-8, 1e-14, 1.05},
                        Case{"geometric r=1.2 rtol 1e-6", Method::Geometric, 1e-6, 1e-12, 1.2}})
    measure(c, repeats);
  return 0;
}
