#include "simulate/run/resume_point.h"

#include "common/error.h"
#include "common/trajectory/resume_frame.h"
#include "simulate/start/configuration_check.h"

namespace coolgas {

ResumePoint read_resume_point(const std::string& path) {
  ResumeFrame f = read_resume_frame(path);
  ResumePoint rp;
  rp.scene_toml = f.params.scene_toml;
  rp.time = f.time;
  rp.counters.collisions = f.collisions;
  rp.counters.below_delta = f.below_delta;
  rp.particles.L = f.params.L;
  rp.particles.resize(f.particles);
  for (std::size_t i = 0; i < f.particles; ++i) {
    rp.particles.r[i] = {f.position[3 * i], f.position[3 * i + 1], f.position[3 * i + 2]};
    rp.particles.v[i] = {f.velocity[3 * i], f.velocity[3 * i + 1], f.velocity[3 * i + 2]};
    rp.particles.image[i] = {f.image[3 * i], f.image[3 * i + 1], f.image[3 * i + 2]};
    rp.particles.t[i] = f.time;
  }
  const std::vector<double>& w = f.angular_velocity;  // rough runs only
  for (std::size_t i = 0; 3 * i < w.size(); ++i) rp.particles.omega.push_back({w[3 * i], w[3 * i + 1], w[3 * i + 2]});
  if (f.aggregates) rp.aggregates = AggregateState{std::move(f.mass), std::move(f.diameter), std::move(f.id)};
  // A mixture's species, each an index into the file's species table, and with them the diameters.
  std::vector<double> diameters;
  const std::vector<double>& table = f.params.species_diameter;
  for (std::size_t i = 0; i < f.species.size(); ++i) {
    const std::int32_t k = f.species[i];
    if (k < 0 || std::size_t(k) >= table.size() || table.size() != f.params.species_fraction.size())
      throw InputError("cannot resume from '" + path + "': particle " + std::to_string(i) + " is of species " +
                       std::to_string(k) + "; the file's table has " + std::to_string(table.size()));
    rp.particles.species.push_back(std::uint8_t(k));
    diameters.push_back(table[std::size_t(k)]);
  }
  check_configuration(rp.particles, rp.aggregates ? &*rp.aggregates : nullptr, "cannot resume from '" + path + "'",
                      Geometry(f.dimension), f.species.empty() ? nullptr : &diameters);
  return rp;
}

}  // namespace coolgas
