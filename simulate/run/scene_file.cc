#include "simulate/run/scene_file.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>

#include "common/error.h"
#include "common/trajectory/collision_models.h"
#include "simulate/start/initial_state.h"

namespace coolgas {

// The scene's text. A directory opens like a file on Linux and reads as
// nothing, an empty scene, so it is refused by name; at most one byte more
// than a scene may hold is read (parse_scene refuses that), so a device such
// as /dev/zero cannot fill the memory.
std::string read_scene_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("scene '" + shown(path) + "' is a directory; give a scene file (TOML)");
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError("cannot read scene '" + shown(path) + "': " + std::strerror(errno));
  std::string text(kMaxSceneBytes + 1, '\0');
  f.read(text.data(), std::streamsize(text.size()));
  if (f.bad()) throw InputError("cannot read scene '" + shown(path) + "': " + std::strerror(errno));
  text.resize(std::size_t(f.gcount()));
  return text;
}

RunParameters parameters_of(const Scene& s) {
  RunParameters p;
  p.scene_toml = s.to_toml();
  p.seed = s.seed;
  p.N = s.N;
  p.L = s.L;
  p.phi = s.phi;
  p.T0 = initial_temperature(s);
  p.model = s.model_name();
  // Only the parameters the model has (common/trajectory/collision_models.h):
  // each the scene's key collision.<name>, or the value its files fix.
  const CollisionModelSpec& model = collision_models().at(std::size_t(s.model));
  p.collision.clear();
  // A parameter at its `off` value (beta = -1) is left out, as the scene's text leaves it.
  for (const ModelParameter* m : model.parameters)
    if (!m->off || s.parameter(m->name) != *m->off) p.collision[std::string(m->name)] = s.parameter(m->name);
  for (const FixedParameter& f : model.fixed) p.collision[std::string(f.parameter->name)] = f.value;
  if (s.driving_power) {
    p.driving_power = s.driving_power;
    p.driving_period = s.driving_period;
  }
  if (s.rough()) p.inertia = s.particle_inertia();
  for (std::size_t k = 0; k < s.species.size(); ++k) {
    p.species_fraction.push_back(s.species[k].fraction);
    p.species_diameter.push_back(s.species[k].diameter);
    p.species_mass.push_back(s.species_mass(k));
  }
  return p;
}

}  // namespace coolgas
