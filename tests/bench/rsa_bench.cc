// Random sequential addition speed: wall and CPU seconds of the random
// start (initial_state with no equilibration: placement by random sequential
// addition, then Maxwellian velocities) and its peak memory per particle,
// for N unit spheres at each volume fraction given (default N = 10^6 at
// phi = 0.35; the issue asks for that "in seconds").
// usage: rsa_bench [N] [phi ...]
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

#include "simulate/start/initial_state.h"
#include "tests/bench/process_stats.h"

namespace {

using coolgas::bench::cpu_seconds;
using coolgas::bench::status_bytes;

void run(std::int64_t n, double phi) {
  coolgas::Scene s;
  s.N = n;
  s.phi = phi;
  s.L = std::cbrt(double(n) * M_PI / (6.0 * phi));
  s.equilibrate = 0;  // the placement itself
  s.t_end = 1;
  // What the process holds before any particle exists (code, libraries):
  // subtracted so the figure is the placement's own bytes per particle.
  const double baseline = status_bytes("VmRSS:");
  const auto t0 = std::chrono::steady_clock::now();
  const double cpu0 = cpu_seconds();
  const coolgas::Particles p = coolgas::initial_state(s);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double cpu = cpu_seconds() - cpu0;
  std::printf("RSA\tN=%lld\tphi=%.3f\twall=%.2fs\tcpu=%.2fs\tpeak_bytes/particle=%.0fB\n", (long long)p.size(), phi, wall,
              cpu, (status_bytes("VmHWM:") - baseline) / double(n));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const std::int64_t n = argc > 1 ? std::atoll(argv[1]) : 1000000;
  std::vector<double> phis;
  for (int k = 2; k < argc; ++k) phis.push_back(std::atof(argv[k]));
  if (phis.empty()) phis.push_back(0.35);
  try {
    if (n < 100) throw std::invalid_argument("N = " + std::string(argc > 1 ? argv[1] : "") + " is below 100");
    for (const double phi : phis)
      if (!(phi > 0 && phi < 0.74)) throw std::invalid_argument("phi must lie in (0, 0.74)");
    // Each volume fraction in a process of its own, so that its peak memory is its own.
    for (const double phi : phis) {
      const pid_t child = fork();
      if (child == 0) {
        run(n, phi);
        std::exit(0);
      }
      int status = 0;
      if (child < 0 || waitpid(child, &status, 0) < 0 || !WIFEXITED(status)) return 1;
      if (WEXITSTATUS(status) != 0) return WEXITSTATUS(status);
    }
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "rsa_bench: %s (usage: rsa_bench [N] [phi ...])\n", e.what());
    return 2;
  } catch (const std::exception& e) {  // in a child: one line, and the status tells the parent
    std::fprintf(stderr, "rsa_bench: %s\n", e.what());
    return 2;
  }
}
