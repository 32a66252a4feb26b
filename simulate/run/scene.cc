#include "simulate/run/scene.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <toml.hpp>

#include "common/error.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"

namespace coolgas {

const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = {
      {"system.N", "integer", "number of particles (>= 2); give two of N, L, phi"},
      {"system.L", "float", "box side, in particle diameters"},
      {"system.phi", "float", "volume fraction N*pi/(6 L^3), in (0, 0.36] for init=random, (0, 0.74] for fcc"},
      {"system.seed", "integer", "random seed for initial positions and velocities (default 1)"},
      {"system.init", "string", "initial positions: \"random\" (random sequential addition, default) or \"fcc\""},
      {"system.equilibrate", "float",
       "elastic collision times run before t = 0 so the positions form an equilibrium fluid, then velocities "
       "are drawn afresh (default 5; 0 starts from the raw packing)"},
      {"collision.model", "string",
       "\"elastic\" (default), \"inelastic\" (paper Eq. 1 with the delta cut-off), \"viscoelastic\" (restitution "
       "rising to 1 as the impact speed falls; see collision.viscoelastic_b) or \"aggregation\" (ballistic "
       "aggregation: spheres that touch merge, volumes add, momentum conserved)"},
      {"collision.r0", "float", "coefficient of restitution, in (0, 1] (inelastic)"},
      {"collision.delta", "float",
       "cut-off: collisions with normal relative speed below delta are elastic, >= 0, in units of "
       "diameter per initial collision time (inelastic, viscoelastic; the paper uses 1e-4; default 0)"},
      {"collision.viscoelastic_b", "float",
       "viscoelastic material constant b = A alpha^{2/5} (Schwager & Poeschel 1998), > 0, in units of "
       "(diameter per initial collision time)^(-1/5): r = 1 - 1.15344 b v^(1/5) + 0.79826 b^2 v^(2/5) - ... for "
       "normal impact speed v (viscoelastic)"},
      {"run.t_end", "float", "simulated time to stop at, > 0, in initial mean collision times"},
      {"output.observables_per_decade", "integer", "observables recorded per decade of time (default 20)"},
      {"output.dumps_per_decade", "integer", "trajectory dumps per decade of time (default 5)"},
      {"output.t_min", "float", "first time of the log-spaced grids, > 0 (default 0.01)"},
      {"output.dump_times", "array of floats", "extra dump times, e.g. [5, 10, 2000]"},
  };
  return keys;
}

bool key_changeable_on_resume(const std::string& key) {
  return key.rfind("run.", 0) == 0 || key.rfind("output.", 0) == 0;
}

namespace {

std::size_t edit_distance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j)
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::string did_you_mean(const std::string& key) {
  std::string best;
  std::size_t best_d = 4;  // suggest only close matches
  for (const auto& k : scene_keys()) {
    const std::size_t d = edit_distance(key, k.key);
    if (d < best_d) best_d = d, best = k.key;
  }
  if (best.empty()) return "";
  return " (did you mean '" + best + "'?)";
}

// Flattens nested tables into dotted keys: {"system.N": value, ...}.
void flatten(const toml::value& v, const std::string& prefix, std::map<std::string, toml::value>& out) {
  if (v.is_table()) {
    for (const auto& [k, sub] : v.as_table()) flatten(sub, prefix.empty() ? k : prefix + "." + k, out);
  } else {
    out[prefix] = v;
  }
}

toml::value parse_toml(const std::string& text, const std::string& source) {
  std::istringstream in(text);
  try {
    return toml::parse(in, source);
  } catch (const std::exception& e) {
    std::string msg = e.what();
    std::replace(msg.begin(), msg.end(), '\n', ' ');
    throw InputError(source + ": not valid TOML: " + msg);
  }
}

// "key=value" -> (key, value), the value parsed as TOML, else as a string.
std::pair<std::string, toml::value> parse_override(const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + kv + "': expected key=value, e.g. --set collision.r0=0.1");
  const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
  std::istringstream in("v = " + value);
  try {
    return {key, toml::find(toml::parse(in, "--set"), "v")};
  } catch (const std::exception&) {
    return {key, toml::value(value)};
  }
}

double as_float(const std::string& key, const toml::value& v) {
  if (v.is_floating()) return v.as_floating();
  if (v.is_integer()) return double(v.as_integer());
  throw InputError(key + " must be a number, got " + toml::format(v));
}

std::int64_t as_int(const std::string& key, const toml::value& v) {
  if (v.is_integer()) return v.as_integer();
  throw InputError(key + " must be an integer, got " + toml::format(v));
}

std::string as_string(const std::string& key, const toml::value& v) {
  if (v.is_string()) return v.as_string();
  throw InputError(key + " must be a string, got " + toml::format(v));
}

[[noreturn]] void out_of_range(const std::string& key, double value, const std::string& allowed) {
  throw InputError(key + " = " + format_number(value) + " is out of range: " + allowed);
}

void set_size(Scene& s, const std::map<std::string, toml::value>& kv) {
  const bool hasN = kv.count("system.N"), hasL = kv.count("system.L"), hasPhi = kv.count("system.phi");
  if (int(hasN) + int(hasL) + int(hasPhi) < 2)
    throw InputError("the scene must give two of system.N, system.L and system.phi");
  if (hasN) s.N = as_int("system.N", kv.at("system.N"));
  if (hasL) s.L = as_float("system.L", kv.at("system.L"));
  if (hasPhi) s.phi = as_float("system.phi", kv.at("system.phi"));
  if (hasPhi && !(s.phi > 0)) out_of_range("system.phi", s.phi, "must be > 0");
  if (hasL && !(s.L > 0)) out_of_range("system.L", s.L, "must be > 0");
  if (!hasN) s.N = std::llround(s.phi * 6.0 * s.L * s.L * s.L / M_PI);
  if (s.N < 2) out_of_range("system.N", double(s.N), "need at least 2 particles");
  if (!hasL) s.L = std::cbrt(double(s.N) * M_PI / (6.0 * s.phi));
  const double phi_of = double(s.N) * M_PI / (6.0 * s.L * s.L * s.L);
  if (hasN && hasL && hasPhi && std::fabs(phi_of - s.phi) > 1e-9 * s.phi)
    throw InputError("system.N, system.L and system.phi disagree: N pi/(6 L^3) = " + format_number(phi_of) +
                     " but phi = " + format_number(s.phi) + "; give only two of them");
  s.phi = phi_of;
}

void check_ranges(const Scene& s) {
  if (s.init == InitialPositions::kRandom && s.phi > kMaxRandomPhi)
    out_of_range("system.phi", s.phi,
                 "random sequential addition reaches phi <= 0.36; use system.init = \"fcc\" (up to 0.74)");
  if (s.init == InitialPositions::kFcc && s.phi > kMaxFccPhi)
    out_of_range("system.phi", s.phi, "an FCC lattice of unit spheres holds phi <= 0.7404");
  if (!(s.equilibrate >= 0)) out_of_range("system.equilibrate", s.equilibrate, "must be >= 0");
  if (!(s.r0 > 0 && s.r0 <= 1)) out_of_range("collision.r0", s.r0, "must be in (0, 1]");
  if (!(s.delta >= 0)) out_of_range("collision.delta", s.delta, "must be >= 0");
  if (!(s.t_end > 0)) out_of_range("run.t_end", s.t_end, "must be > 0 (give the time to simulate to)");
  if (!(s.t_min > 0)) out_of_range("output.t_min", s.t_min, "must be > 0");
  if (s.observables_per_decade < 1)
    out_of_range("output.observables_per_decade", s.observables_per_decade, "must be >= 1");
  if (s.dumps_per_decade < 1) out_of_range("output.dumps_per_decade", s.dumps_per_decade, "must be >= 1");
  for (double t : s.dump_times)
    if (!(t >= 0)) out_of_range("output.dump_times", t, "times must be >= 0");
  const std::string box = check_box_fits_grid(s.L, 1.0);
  if (!box.empty()) throw InputError(box);
}

// Each model takes only its own collision.* keys, so a typo in the model
// name cannot silently drop a parameter.
void check_model_keys(const Scene& s, const std::map<std::string, toml::value>& kv) {
  const std::string model = "collision.model = \"" + s.model_name() + "\"";
  auto refuse = [&](const char* key, const char* fix) {
    if (kv.count(key)) throw InputError(std::string(key) + " is set but " + model + " does not use it; " + fix);
  };
  switch (s.model) {
    case CollisionModel::kElastic:
      if (s.r0 != 1.0 || s.delta != 0.0)
        throw InputError("collision.r0/delta are set but collision.model = \"elastic\"; set model = \"inelastic\"");
      refuse("collision.viscoelastic_b", "set model = \"viscoelastic\"");
      break;
    case CollisionModel::kInelastic:
      refuse("collision.viscoelastic_b", "set model = \"viscoelastic\" or remove it");
      break;
    case CollisionModel::kViscoelastic:
      refuse("collision.r0", "the viscoelastic restitution follows from collision.viscoelastic_b; remove r0");
      if (!(s.viscoelastic_b > 0 && std::isfinite(s.viscoelastic_b)))
        out_of_range("collision.viscoelastic_b", s.viscoelastic_b,
                     "must be > 0 for model = \"viscoelastic\" (e.g. 0.1 gives r = 0.9 at impact speed 1)");
      break;
    case CollisionModel::kAggregation:
      for (const char* key : {"collision.r0", "collision.delta", "collision.viscoelastic_b"})
        refuse(key, "aggregates stick; remove it");
      break;
  }
}

Scene build_scene(const std::map<std::string, toml::value>& kv) {
  Scene s;
  auto get = [&](const char* k) -> const toml::value* {
    auto it = kv.find(k);
    return it == kv.end() ? nullptr : &it->second;
  };
  if (auto v = get("system.seed")) s.seed = as_int("system.seed", *v);
  if (auto v = get("system.init")) {
    const std::string init = as_string("system.init", *v);
    if (init == "random") s.init = InitialPositions::kRandom;
    else if (init == "fcc") s.init = InitialPositions::kFcc;
    else throw InputError("system.init = \"" + init + "\" is not known: use \"random\" or \"fcc\"");
  }
  if (auto v = get("system.equilibrate")) s.equilibrate = as_float("system.equilibrate", *v);
  if (auto v = get("collision.model")) {
    const std::string m = as_string("collision.model", *v);
    if (m == "elastic") s.model = CollisionModel::kElastic;
    else if (m == "inelastic") s.model = CollisionModel::kInelastic;
    else if (m == "viscoelastic") s.model = CollisionModel::kViscoelastic;
    else if (m == "aggregation") s.model = CollisionModel::kAggregation;
    else
      throw InputError("collision.model = \"" + m +
                       "\" is not known: use \"elastic\", \"inelastic\", \"viscoelastic\" or \"aggregation\"");
  }
  if (auto v = get("collision.r0")) s.r0 = as_float("collision.r0", *v);
  if (auto v = get("collision.delta")) s.delta = as_float("collision.delta", *v);
  if (auto v = get("collision.viscoelastic_b")) s.viscoelastic_b = as_float("collision.viscoelastic_b", *v);
  check_model_keys(s, kv);
  if (auto v = get("run.t_end")) s.t_end = as_float("run.t_end", *v);
  else throw InputError("the scene must give run.t_end (the simulated time to stop at)");
  if (auto v = get("output.observables_per_decade")) s.observables_per_decade = int(as_int("output.observables_per_decade", *v));
  if (auto v = get("output.dumps_per_decade")) s.dumps_per_decade = int(as_int("output.dumps_per_decade", *v));
  if (auto v = get("output.t_min")) s.t_min = as_float("output.t_min", *v);
  if (auto v = get("output.dump_times")) {
    if (!v->is_array()) throw InputError("output.dump_times must be an array of times, e.g. [5, 10]");
    for (const auto& t : v->as_array()) s.dump_times.push_back(as_float("output.dump_times", t));
  }
  set_size(s, kv);
  check_ranges(s);
  return s;
}

}  // namespace

Scene parse_scene(const std::string& toml_text, const std::string& source, const std::vector<std::string>& overrides) {
  std::map<std::string, toml::value> kv;
  flatten(parse_toml(toml_text, source), "", kv);
  for (const auto& o : overrides) {
    auto [key, value] = parse_override(o);
    kv[key] = value;
  }
  for (const auto& [key, value] : kv) {
    const bool known = std::any_of(scene_keys().begin(), scene_keys().end(),
                                   [&](const SceneKey& k) { return key == k.key; });
    if (!known) throw InputError("unknown scene key '" + key + "'" + did_you_mean(key));
  }
  return build_scene(kv);
}

std::string Scene::model_name() const {
  switch (model) {
    case CollisionModel::kElastic: return "elastic";
    case CollisionModel::kInelastic: return "inelastic";
    case CollisionModel::kViscoelastic: return "viscoelastic";
    case CollisionModel::kAggregation: return "aggregation";
  }
  return "?";
}

std::string Scene::to_toml() const {
  std::ostringstream s;
  auto num = [](double x) {  // a TOML float that reads back to the same double
    std::string t = format_number(x);
    if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
    return t;
  };
  s << "# coolgas scene: the effective values (file, --set overrides and defaults)\n"
    << "[system]\nN = " << N << "\nL = " << num(L) << "\nphi = " << num(phi) << "\nseed = " << seed
    << "\ninit = \"" << (init == InitialPositions::kRandom ? "random" : "fcc") << "\"\nequilibrate = " << num(equilibrate)
    << "\n\n"
    << "[collision]\nmodel = \"" << model_name() << "\"\n";
  if (model == CollisionModel::kInelastic) s << "r0 = " << num(r0) << "\ndelta = " << num(delta) << "\n";
  if (model == CollisionModel::kViscoelastic)
    s << "viscoelastic_b = " << num(viscoelastic_b) << "\ndelta = " << num(delta) << "\n";
  s << "\n[run]\nt_end = " << num(t_end) << "\n\n[output]\nobservables_per_decade = " << observables_per_decade
    << "\ndumps_per_decade = " << dumps_per_decade << "\nt_min = " << num(t_min) << "\ndump_times = [";
  for (std::size_t i = 0; i < dump_times.size(); ++i) s << (i ? ", " : "") << num(dump_times[i]);
  s << "]\n";
  return s.str();
}

}  // namespace coolgas
