// coolgas-velocity: velocity statistics of every dump of a trajectory (the
// paper's Fig. 5): the scaled distribution Φ(y), its tail -ln Φ(y) with the
// fitted exponent β, and the kurtosis κ.
#pragma once
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace coolgas {

enum class VelocityTable {
  kPhi,    // one block per dump: t y Phi Phi_err minus_ln_Phi
  kTail,   // one block per dump: t y minus_ln_Phi minus_ln_Phi_err fit (the fitted points)
  kSeries  // one row per dump: t v_rms kappa kappa_err beta beta_err tail_points
};

struct VelocityOptions {
  std::string input;
  VelocityTable table = VelocityTable::kPhi;
  int bins = 120;             // histogram bins over [-ymax, ymax] (even)
  double ymax = 6;            // range of y = v_alpha / v_rms
  double tail_from = 1.5;     // fit the tail for y >= tail_from
  double min_count = 25;      // fit only bins with at least this many samples (both signs)
  std::vector<double> times;  // dumps nearest these times; empty = all dumps
  bool exact_time = false;  // --exact-time: refuse a time no dump has
  // --spins: the same statistics of a rough run's angular velocities, over
  // their d_r spinning axes (3 for spheres, z alone for disks) instead of the d velocity components.
  bool spins = false;
  // --species K: only the particles of a mixture's species K (its index in
  // the file: 0 for the first [[species]] table); absent: every particle.
  std::optional<int> species;
};

void run_velocity(const VelocityOptions& opt, std::ostream& out);

}  // namespace coolgas
