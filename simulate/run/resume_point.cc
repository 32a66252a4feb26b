#include "simulate/run/resume_point.h"

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
  check_configuration(rp.particles, rp.aggregates ? &*rp.aggregates : nullptr, "cannot resume from '" + path + "'",
                      Geometry(f.dimension));
  return rp;
}

}  // namespace coolgas
