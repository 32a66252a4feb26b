#include "simulate/start/initial_state.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>

#include "common/error.h"
#include "common/fault_point.h"
#include "common/tsv.h"
#include "simulate/engine/engine.h"
#include "common/random.h"
#include "common/geometry.h"
#include "simulate/scene/mixture_rule.h"
#include "simulate/start/mixture_enskog.h"
#include "simulate/start/rod_placement.h"
#include "simulate/start/rsa_disks.h"
#include "simulate/start/rsa_mixture.h"
#include "simulate/start/rsa_voxels.h"

namespace coolgas {

namespace {

// N of the 4k³ sites of the smallest FCC lattice holding N, chosen at random.
void place_fcc(Particles& p, std::int64_t N, Random& rng) {
  const auto k = static_cast<std::int64_t>(std::ceil(std::cbrt(double(N) / 4.0) - 1e-12));
  const std::int64_t sites = 4 * k * k * k;
  const double a = p.L / double(k);
  if (a / std::sqrt(2.0) < 1.0 + 1e-9)
    throw InputError("system.phi = " + format_number(double(N) * M_PI / (6 * p.L * p.L * p.L)) +
                     " is too dense for an FCC lattice of " + std::to_string(sites) +
                     " sites in this box (neighbour distance " + format_number(a / std::sqrt(2.0)) +
                     " < 1); lower phi or choose N = 4k^3");
  std::vector<std::int64_t> idx(static_cast<std::size_t>(sites));
  std::iota(idx.begin(), idx.end(), 0);
  for (std::int64_t i = 0; i < N; ++i) std::swap(idx[i], idx[i + std::int64_t(rng.below(std::uint64_t(sites - i)))]);
  std::sort(idx.begin(), idx.begin() + N);
  static const double basis[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  for (std::int64_t i = 0; i < N; ++i) {
    const std::int64_t s = idx[i], cell = s / 4, b = s % 4;
    const std::int64_t cx = cell % k, cy = (cell / k) % k, cz = cell / (k * k);
    p.r[i] = {(double(cx) + basis[b][0] + 0.25) * a, (double(cy) + basis[b][1] + 0.25) * a,
              (double(cz) + basis[b][2] + 0.25) * a};
  }
}

// "0.2117" (a phi computed from N and L has noise digits), for the set-up's progress line.
std::string four_digits(double x) { return format_number(std::round(1e4 * x) / 1e4); }

// "37 %", for the set-up's progress line.
std::string percent(double part, double whole) {
  return std::to_string(int(std::min(100.0, 100 * part / whole))) + " %";
}

}  // namespace

// With unit masses every product and quotient by a mass is exact, so the
// velocities are those of the plain unit-sphere formula, bit for bit.
// The temperature is the kinetic energy over the dimension's D/2 per
// particle, so in 2D the sum of squares is scaled to 2 N T0, not 3 N T0
// (in 1D to N T0).
void draw_velocities(Particles& p, double T0, Random& rng, const std::vector<double>* mass, Geometry g) {
  const auto m = [&](std::size_t i) { return mass ? (*mass)[i] : 1.0; };
  Vec3 momentum;
  double total_mass = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3& v = p.v[i];
    for (int k = 0; k < 3; ++k) v[k] = k < g.d() ? rng.normal() : 0.0;  // x, y, z in turn: the same draws
    const double root = mass ? std::sqrt(m(i)) : 1.0;
    for (int d = 0; d < 3; ++d) {
      v[d] /= root;
      momentum[d] += m(i) * v[d];
    }
    total_mass += m(i);
  }
  double sum2 = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    Vec3& v = p.v[i];
    for (int d = 0; d < 3; ++d) v[d] -= momentum[d] / total_mass;
    sum2 += m(i) * dot(v, v);
  }
  const double scale = std::sqrt(2 * g.energy_per_temperature() * T0 * double(p.size()) / sum2);
  for (auto& v : p.v)
    for (int d = 0; d < 3; ++d) v[d] *= scale;
}

// I = q a² = q/4 for unit diameter and mass. The spinning axes are the last
// rotational_axes() of the three: all in 3D, z alone in 2D.
void draw_spins(Particles& p, double T0, double inertia, Random& rng, Geometry g) {
  p.omega.assign(p.size(), Vec3{});
  double sum2 = 0;
  for (Vec3& w : p.omega) {
    for (int k = 3 - g.rotational_axes(); k < 3; ++k) w[k] = rng.normal();
    sum2 += dot(w, w);
  }
  const double scale = std::sqrt(double(g.rotational_axes()) * T0 * double(p.size()) / (0.25 * inertia * sum2));
  for (Vec3& w : p.omega)
    for (int k = 0; k < 3; ++k) w[k] *= scale;
}

constexpr std::int64_t kEquilibrationSlice = 1 << 18;  // events between progress updates

namespace {

// The positions after `duration` collision times of elastic dynamics in
// dimension D. Only they are kept (velocities are drawn afresh), and only
// they coexist with the engine: this is the set-up's memory peak.
template <int D, class Rule, class Say>
std::vector<Vec3> equilibrated(Particles p, const Rule& rule, double duration, InterruptFlag interrupt,
                               const Say& say) {
  Engine<Rule, D> melt(std::move(p), rule, 0.0);
  // In slices, for the progress line (slicing a run changes nothing: the engine contract).
  RunStatus status = RunStatus::kEventBudget;
  while (status == RunStatus::kEventBudget) {
    status = melt.run_until(duration, kEquilibrationSlice, interrupt);
    if (status == RunStatus::kInterrupted) throw SetupInterrupted();
    fault_point(FaultPoint::kEquilibration);  // a test's signal here: seen within the next 4096 events
    say("equilibrating: t = " + format_number(std::round(melt.now() * 100) / 100) + " / " + format_number(duration) +
            " elastic collision times (" + percent(melt.now(), duration) + ")",
        false);
  }
  return melt.release_positions();
}

// The melt in the scene's dimension: unit spheres' (ElasticRule) or a
// mixture's (its contact distances and masses).
template <class Rule, class Say>
std::vector<Vec3> equilibrated_in(Geometry g, Particles p, const Rule& rule, double duration, InterruptFlag interrupt,
                                  const Say& say) {
  return g.dispatch([&]<int D>() { return equilibrated<D>(std::move(p), rule, duration, interrupt, say); });
}

// Each particle's species (ids follow the [[species]] tables: species 0
// first) and mass.
std::vector<std::uint8_t> species_of_particles(const Scene& s) {
  std::vector<std::uint8_t> species;
  const auto counts = s.species_counts();
  for (std::size_t k = 0; k < counts.size(); ++k)
    species.insert(species.end(), std::size_t(counts[k]), std::uint8_t(k));
  return species;
}

std::vector<double> particle_masses(const Scene& s, const std::vector<std::uint8_t>& species) {
  std::vector<double> mass(species.size());
  for (std::size_t i = 0; i < species.size(); ++i) mass[i] = s.species_mass(species[i]);
  return mass;
}

// The mixture's start: random placement largest first (rods: exact), the
// elastic melt, Maxwellians at T0 per species (per component m_k <v_x^2> =
// T0), the total momentum 0 and the whole rescaled to T0.
Particles mixture_state(const Scene& s, InterruptFlag interrupt, const SetupReport& report) {
  const auto say = [&](const std::string& line, bool phase) {
    if (report) report(line, phase);
  };
  say("placing a mixture of " + std::to_string(s.N) + " particles at random" + s.geometry().in_d(), true);
  Particles p;
  p.L = s.L;
  p.resize(std::size_t(s.N));
  p.species = species_of_particles(s);
  const std::vector<double> mass = particle_masses(s, p.species);
  const MixtureRule<ElasticRule> rule = mixture_rule(s, ElasticRule{});
  Random rng(std::uint64_t(s.seed));
  place_random_mixture(p, species_diameters(s), s.geometry(), rng, interrupt, [&](std::int64_t n) {
    say("placing at random: " + std::to_string(n) + " of " + std::to_string(s.N) + " (" + percent(n, s.N) + ")",
        false);
  });
  const double T0 = initial_temperature(s);
  draw_velocities(p, T0, rng, &mass, s.geometry());
  if (s.equilibrate > 0) {
    say("equilibrating: " + format_number(s.equilibrate) + " elastic collision times", true);
    std::vector<std::uint8_t> species = p.species;
    std::vector<Vec3> relaxed = equilibrated_in(s.geometry(), std::move(p), rule, s.equilibrate, interrupt, say);
    p = Particles();
    p.L = s.L;
    p.resize(relaxed.size());
    p.r = std::move(relaxed);
    p.species = std::move(species);
    draw_velocities(p, T0, rng, &mass, s.geometry());
  }
  return p;
}

}  // namespace

double initial_temperature(const Scene& s) {
  if (s.T0 > 0) return s.T0;  // a start from a file (simulate/start/file_start.h)
  if (s.mixture()) return mixture_unit_time_temperature(s);
  return s.geometry().unit_time_temperature(double(s.N) / s.geometry().box_measure(s.L), s.phi);
}

double initial_energy(const Scene& s) { return s.geometry().energy_per_temperature() * initial_temperature(s); }

Particles initial_state(const Scene& s, InterruptFlag interrupt, const SetupReport& report) {
  if (s.mixture()) return mixture_state(s, interrupt, report);
  const auto say = [&](const std::string& line, bool phase) {
    if (report) report(line, phase);
  };
  say("placing " + std::to_string(s.N) + (s.init == InitialPositions::kRandom ? " particles at random" : " particles on FCC") +
          s.geometry().in_d(),
      true);
  Particles p;
  p.L = s.L;
  // Positions first, the other arrays only after the placement: its search
  // structures and the positions are the set-up's memory peak.
  p.r.resize(std::size_t(s.N));
  Random rng(std::uint64_t(s.seed));
  const auto placed = [&](std::int64_t n) {
    say("placing at random: " + std::to_string(n) + " of " + std::to_string(s.N) + " (" + percent(n, s.N) +
            "), phi = " + four_digits(s.geometry().covered_fraction(double(n), s.L)) + " of " + four_digits(s.phi),
        false);
  };
  if (s.dimension == 1) place_rods(p, s.N, rng, interrupt, placed);  // the scene allows no other 1D start
  else if (s.dimension == 2) place_random_disks(p, s.N, rng, interrupt, placed);  // nor 2D
  else if (s.init == InitialPositions::kRandom) place_random_sequential(p, s.N, rng, interrupt, placed);
  else place_fcc(p, s.N, rng);
  p.resize(std::size_t(s.N));
  const double T0 = initial_temperature(s);
  draw_velocities(p, T0, rng, nullptr, s.geometry());
  if (s.equilibrate > 0) {
    say("equilibrating: " + format_number(s.equilibrate) + " elastic collision times", true);
    std::vector<Vec3> relaxed =
        equilibrated_in(s.geometry(), std::move(p), ElasticRule{}, s.equilibrate, interrupt, say);
    p = Particles();
    p.L = s.L;
    p.resize(relaxed.size());
    p.r = std::move(relaxed);
    draw_velocities(p, T0, rng, nullptr, s.geometry());
  }
  if (s.rough()) draw_spins(p, T0, s.particle_inertia(), rng, s.geometry());
  return p;
}

}  // namespace coolgas
