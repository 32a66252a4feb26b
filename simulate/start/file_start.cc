#include "simulate/start/file_start.h"

#include <cmath>
#include <sstream>

#include "common/error.h"
#include "common/random.h"
#include "common/tsv.h"
#include "common/geometry.h"
#include "simulate/start/configuration_check.h"
#include "simulate/start/configuration_file.h"
#include "simulate/start/initial_state.h"

namespace coolgas {

namespace {

// Diameters and masses as the model allows them: unit particles for the gas
// models, the file's aggregates for ballistic aggregation.
void set_spheres(FileConfiguration& c, CollisionModel model, const std::string& source) {
  const std::size_t n = c.position.size() / 3;
  const bool aggregates = model == CollisionModel::kAggregation;
  for (std::size_t i = 0; i < n; ++i) {
    if (!c.mass.empty() && !(std::isfinite(c.mass[i]) && c.mass[i] > 0))
      throw InputError(source + ": particle " + std::to_string(i) + " has mass " + format_number(c.mass[i]) +
                       "; masses are finite and > 0");
    if (aggregates) continue;
    const bool unit = (c.diameter.empty() || c.diameter[i] == 1) && (c.mass.empty() || c.mass[i] == 1);
    if (!unit)
      throw InputError(source + ": particle " + std::to_string(i) + " has diameter " +
                       format_number(c.diameter.empty() ? 1 : c.diameter[i]) + " and mass " +
                       format_number(c.mass.empty() ? 1 : c.mass[i]) +
                       "; only collision.model = \"aggregation\" has " + Geometry(c.dimension).particles() +
                       " other than diameter 1, mass 1");
  }
  if (!aggregates) {
    c.diameter.clear();
    c.mass.clear();
    return;
  }
  const Geometry g(c.dimension);
  if (c.diameter.empty()) {
    c.diameter.resize(n, 1.0);
    for (std::size_t i = 0; i < c.mass.size(); ++i) c.diameter[i] = g.diameter_of_mass(c.mass[i]);
  }
  if (c.mass.empty()) {
    c.mass.resize(n);
    for (std::size_t i = 0; i < n; ++i) c.mass[i] = g.mass_of_diameter(c.diameter[i]);
  }
}

// The fraction of the box the particles cover (Geometry's, with each
// particle's own diameter).
double volume_fraction(const FileConfiguration& c, std::size_t n) {
  const Geometry g(c.dimension);
  double v = 0;
  for (std::size_t i = 0; i < n; ++i) v += c.diameter.empty() ? 1.0 : g.mass_of_diameter(c.diameter[i]);
  return g.covered_fraction(v, c.L);
}

// The file's dimension must be the scene's: a frame of disks is not a start for spheres.
void check_dimension(const Scene& s, const FileConfiguration& c, const std::string& source) {
  if (c.dimension == s.dimension) return;
  static const char* const kBoxes[] = {"", "a ring (pbc=\"T F F\" or box/dimension 1)",
                                       "a square box (pbc=\"T T F\" or box/dimension 2)", "a cubic box"};
  throw InputError(source + " holds " + Geometry(c.dimension).particles() + " in " + kBoxes[c.dimension] +
                   " but system.dimension = " + std::to_string(s.dimension) + "; set system.dimension = " +
                   std::to_string(c.dimension));
}

// N, L, phi of the file, checked against those the scene gives.
void take_size(Scene& s, std::size_t n, double L, double phi, const std::string& source) {
  const std::string leave = " (leave system.N, L and phi out: they come from the file)";
  if (s.N > 0 && std::size_t(s.N) != n)
    throw InputError("system.N = " + std::to_string(s.N) + " but " + source + " holds " + std::to_string(n) +
                     " particles" + leave);
  if (s.L > 0 && s.L != L)
    throw InputError("system.L = " + format_number(s.L) + " but the box of " + source + " has side " +
                     format_number(L) + leave);
  if (s.phi > 0 && std::fabs(s.phi - phi) > 1e-9 * phi)
    throw InputError("system.phi = " + format_number(s.phi) + " but the " + s.geometry().particles() + " of " +
                     source + " cover " + format_number(phi) + " of the box" + leave);
  s.N = std::int64_t(n);
  s.L = L;
  s.phi = phi;
}

std::string three_digits(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// Σ m v² / (D N): the temperature per velocity component.
double temperature(const Particles& p, const std::vector<double>& mass, Geometry g) {
  double sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) sum += (mass.empty() ? 1.0 : mass[i]) * dot(p.v[i], p.v[i]);
  return sum / (2 * g.energy_per_temperature() * double(p.size()));
}

// Positions as they are; velocities the file's, else drawn at T0 (masses set
// first); rough particles' spins the file's (a rough coolgas run's), else
// drawn at T0 after the velocities.
Particles particles_of(const FileConfiguration& c, const Scene& s) {
  const std::size_t n = c.position.size() / 3;
  Particles p;
  p.L = c.L;
  p.resize(n);
  const auto vec = [](const std::vector<double>& x, std::size_t i) { return Vec3{x[3 * i], x[3 * i + 1], x[3 * i + 2]}; };
  for (std::size_t i = 0; i < n; ++i) p.r[i] = vec(c.position, i);
  Random rng(std::uint64_t(s.seed));
  if (c.velocity.empty()) {
    draw_velocities(p, s.T0, rng, c.mass.empty() ? nullptr : &c.mass, s.geometry());
  } else {
    for (std::size_t i = 0; i < n; ++i) p.v[i] = vec(c.velocity, i);
  }
  if (!s.rough()) return p;
  if (c.angular_velocity.empty()) {
    draw_spins(p, s.T0, s.particle_inertia(), rng, s.geometry());
  } else {
    for (std::size_t i = 0; i < n; ++i) p.omega.push_back(vec(c.angular_velocity, i));
  }
  return p;
}

// "starting from 'f.xyz' (extended XYZ, t = 5): N = 2000, L = 17.4, phi = 0.2;
// velocities from the file (0.404 T0); T0 = 0.0441 (the file's)".
std::string notice(const Scene& s, const FileConfiguration& c, const FileStart& start, bool drawn, bool own_T0) {
  const std::vector<double> unit;
  const double T = temperature(start.particles, start.aggregates ? start.aggregates->mass : unit, s.geometry());
  const std::string velocities = drawn ? "drawn at T0" : "from the file (" + three_digits(T / s.T0) + " T0)";
  const std::string T0 = own_T0 ? "system.T0" : c.T0 ? "the file's" : "Enskog, as for a fresh start";
  return "starting from '" + s.from + "' (" + c.format + (c.time ? ", t = " + format_number(*c.time) : "") +
         "): N = " + std::to_string(s.N) + ", L = " + format_number(s.L) + ", phi = " + three_digits(s.phi) +
         "; velocities " + velocities +
         (s.rough() ? std::string("; spins ") + (c.angular_velocity.empty() ? "drawn at T0" : "from the file") : "") +
         "; T0 = " + format_number(s.T0) + " (" + T0 + ")" +
         (c.length_unit.empty() ? "" : "; the file's length unit '" + c.length_unit + "' is read as one diameter");
}

}  // namespace

FileStart start_from_file(const Scene& given) {
  FileStart start;
  Scene& s = start.scene = given;
  const std::string source = "system.from = '" + s.from + "'";
  FileConfiguration c = read_configuration(s.from, s.from_time);
  const std::size_t n = c.position.size() / 3;
  check_dimension(s, c, source);
  set_spheres(c, s.model, source);
  take_size(s, n, c.L, volume_fraction(c, n), source);
  const std::string close = check_close_packing(s);
  if (!close.empty()) throw InputError(source + ": phi = " + format_number(s.phi) + " is out of range: " + close);
  // The frame's time becomes the run's start, which every --resume checks:
  // a NaN or negative time (another program's H5MD) is refused here, once.
  if (c.time && !(std::isfinite(*c.time) && *c.time >= 0))
    throw InputError(source + ": the frame's time t = " + format_number(*c.time) +
                     " is not a time; times are finite and >= 0");
  if (c.time) s.from_time = c.time;
  const bool own_T0 = s.T0 > 0;
  if (!own_T0) s.T0 = c.T0 ? *c.T0 : s.geometry().unit_time_temperature(double(n) / s.geometry().box_measure(c.L), s.phi);
  check_scene_size(s);

  start.particles = particles_of(c, s);
  const bool drawn = c.velocity.empty();
  if (s.model == CollisionModel::kAggregation) {
    AggregateState a{std::move(c.mass), std::move(c.diameter), std::vector<std::int32_t>(n)};
    for (std::size_t i = 0; i < n; ++i) a.id[i] = std::int32_t(i);
    start.aggregates = std::move(a);
  }
  check_configuration(start.particles, start.aggregates ? &*start.aggregates : nullptr, source, s.geometry());

  start.notice = notice(s, c, start, drawn, own_T0);
  return start;
}

}  // namespace coolgas
