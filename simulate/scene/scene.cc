#include "simulate/scene/scene.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <toml.hpp>

#include "common/did_you_mean.h"
#include "common/error.h"
#include "common/memory.h"
#include "common/trajectory/collision_models.h"
#include "common/tsv.h"
#include "simulate/engine/cell_grid.h"

namespace coolgas {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// The scene's array of [[species]] tables (flattened under this one key).
constexpr const char* kSpeciesKey = "species";
using M = CollisionModel;
using I = InitialPositions;

// A TOML float that reads back to the same double.
std::string toml_float(double x) {
  std::string t = format_number(x);
  if (t.find_first_of(".eEn") == std::string::npos) t += ".0";
  return t;
}
std::string toml_string(const std::string& x) { return "\"" + x + "\""; }

const char* const kInitNames[] = {"random", "fcc", "file"};
// The models' names, in the enum's order (common/trajectory/collision_models.h).
std::vector<std::string> model_names() {
  std::vector<std::string> names;
  for (const CollisionModelSpec& m : collision_models()) names.emplace_back(m.name);
  return names;
}
static_assert(std::size(kInitNames) == std::size_t(InitialPositions::kFile) + 1,
              "kInitNames lists the InitialPositions values in their order");

// Index of `value` among the key's choices (already checked to be one).
template <class Enum>
Enum choice(const SceneKey& k, const SceneValue& v) {
  const auto it = std::find(k.choices.begin(), k.choices.end(), std::get<std::string>(v));
  return Enum(it - k.choices.begin());
}
const SceneKey& key_row(const char* name);

// collision.model's help: each model's summary (common/trajectory/collision_models.h).
std::string model_help() {
  std::string out;
  const auto& models = collision_models();
  for (std::size_t i = 0; i < models.size(); ++i)
    out += std::string(i == 0 ? "" : i + 1 == models.size() ? " or " : ", ") + std::string(models[i].summary);
  return out;
}

// The models whose scenes set `p`.
std::vector<CollisionModel> models_setting(const ModelParameter& p) {
  std::vector<CollisionModel> out;
  const auto& models = collision_models();
  for (std::size_t i = 0; i < models.size(); ++i)
    if (std::find(models[i].parameters.begin(), models[i].parameters.end(), &p) != models[i].parameters.end())
      out.push_back(CollisionModel(i));
  return out;
}

// The key collision.<name> of a model parameter: its range, its default
// (else required by the models that set it), read and written by name.
SceneKey parameter_key(const ModelParameter& p) {
  const std::string name(p.name);
  return {.key = "collision." + name, .type = KeyType::kFloat,
          .need = p.default_value ? KeyNeed::kDefault : KeyNeed::kRequired, .help = std::string(p.help),
          .lo = p.lo, .hi = p.hi, .lo_open = p.lo_open, .hi_open = p.hi_open, .models = models_setting(p),
          .set = [name](Scene& s, const SceneValue& v) { s.set_parameter(name, std::get<double>(v)); },
          .toml = [name, &p](const Scene& s) {
            if (!s.collision.count(name) && !p.default_value) return std::string();
            const double value = s.parameter(name);
            return p.off && value == *p.off ? std::string() : toml_float(value);  // at `off`: the text as before
          }};
}

// The keys, with collision.<name> of every model parameter after collision.model.
std::vector<SceneKey> with_parameter_keys(std::vector<SceneKey> keys) {
  auto at = std::find_if(keys.begin(), keys.end(), [](const SceneKey& k) { return k.key == "collision.model"; });
  std::vector<SceneKey> parameters;
  for (const ModelParameter* p : model_parameters()) parameters.push_back(parameter_key(*p));
  keys.insert(at + 1, parameters.begin(), parameters.end());
  return keys;
}

}  // namespace

// Order matters: to_toml() writes the tables and keys in this order.
const std::vector<SceneKey>& scene_keys() {
  static const std::vector<SceneKey> keys = with_parameter_keys({
      // Written to TOML only when not 3, so that a 3D scene's text (and with
      // it a 3D run's file) is what it was before the key existed.
      {.key = "system.dimension", .type = KeyType::kInteger, .need = KeyNeed::kOptional,
       .help = "1 (hard rods on a periodic ring; phi is then the line fraction), 2 (hard disks in a periodic "
               "square; phi is then the area fraction) or 3 (spheres in a periodic cube); absent: 3",
       .lo = 1, .hi = 3,
       .set = [](Scene& s, const SceneValue& v) { s.dimension = int(std::get<std::int64_t>(v)); },
       .toml = [](const Scene& s) { return s.dimension == Scene{}.dimension ? std::string() : std::to_string(s.dimension); }},
      {.key = "system.N", .type = KeyType::kInteger, .need = KeyNeed::kSize,
       .help = "number of particles; give two of N, L, phi", .lo = 2,
       .set = [](Scene& s, const SceneValue& v) { s.N = std::get<std::int64_t>(v); },
       .toml = [](const Scene& s) { return std::to_string(s.N); }},
      {.key = "system.L", .type = KeyType::kFloat, .need = KeyNeed::kSize, .help = "box side, in particle diameters",
       .lo = 0, .lo_open = true,
       .set = [](Scene& s, const SceneValue& v) { s.L = std::get<double>(v); },
       .toml = [](const Scene& s) { return toml_float(s.L); }},
      {.key = "system.phi", .type = KeyType::kFloat, .need = KeyNeed::kSize,
       .help = "volume fraction N*pi/(6 L^3) (2D: area fraction N*pi/(4 L^2); 1D: line fraction N/L); at most "
               "0.36 for init = \"random\" (2D: 0.45; 1D: below 1), 0.7404 for \"fcc\"",
       .lo = 0, .hi = 1, .lo_open = true, .hi_open = true,
       .set = [](Scene& s, const SceneValue& v) { s.phi = std::get<double>(v); },
       .toml = [](const Scene& s) { return toml_float(s.phi); }},
      {.key = "system.seed", .type = KeyType::kInteger, .need = KeyNeed::kDefault,
       .help = "random seed for initial positions and velocities",
       .set = [](Scene& s, const SceneValue& v) { s.seed = std::get<std::int64_t>(v); },
       .toml = [](const Scene& s) { return std::to_string(s.seed); }},
      {.key = "system.init", .type = KeyType::kString, .need = KeyNeed::kDefault,
       .help = "initial positions: \"random\" (random sequential addition), \"fcc\", or \"file\" (a frame of "
               "system.from; N, L and phi then come from the file)",
       .choices = {std::begin(kInitNames), std::end(kInitNames)},
       .set = [](Scene& s, const SceneValue& v) { s.init = choice<InitialPositions>(key_row("system.init"), v); },
       .toml = [](const Scene& s) { return toml_string(kInitNames[int(s.init)]); }},
      {.key = "system.equilibrate", .type = KeyType::kFloat, .need = KeyNeed::kDefault,
       .help = "elastic collision times run before t = 0 so the positions form an equilibrium fluid, then "
               "velocities are drawn afresh (0 starts from the raw packing)",
       .lo = 0, .inits = {I::kRandom, I::kFcc},
       .set = [](Scene& s, const SceneValue& v) { s.equilibrate = std::get<double>(v); },
       .toml = [](const Scene& s) { return toml_float(s.equilibrate); }},
      {.key = "system.from", .type = KeyType::kString, .need = KeyNeed::kRequired,
       .help = "the file to start from, relative to the working directory: a coolgas trajectory, an H5MD 1.1 file "
               "of another program (particles/<group>/position, box/edges) or an extended XYZ file, of "
               "system.dimension (disks: a square box, rods: a ring); velocities from the file, else drawn at T0 "
               "with system.seed; rough particles' spins likewise (a rough coolgas run's, else drawn at T0)",
       .inits = {I::kFile},
       .set = [](Scene& s, const SceneValue& v) { s.from = std::get<std::string>(v); },
       .toml = [](const Scene& s) { return toml_string(s.from); }},
      {.key = "system.from_time", .type = KeyType::kFloat, .need = KeyNeed::kOptional,
       .help = "start from the file's frame nearest this time (its own time unit); absent: the last frame",
       .lo = 0, .inits = {I::kFile},
       .set = [](Scene& s, const SceneValue& v) { s.from_time = std::get<double>(v); },
       .toml = [](const Scene& s) { return s.from_time ? toml_float(*s.from_time) : std::string(); }},
      {.key = "system.T0", .type = KeyType::kFloat, .need = KeyNeed::kOptional,
       .help = "temperature per velocity component that sets the time unit 1/omega0; absent: a coolgas file's own "
               "T0 (or the T0= of an XYZ comment line), else the Enskog value of the file's density as for a "
               "fresh start",
       .lo = 0, .lo_open = true, .inits = {I::kFile},
       .set = [](Scene& s, const SceneValue& v) { s.T0 = std::get<double>(v); },
       .toml = [](const Scene& s) { return s.T0 > 0 ? toml_float(s.T0) : std::string(); }},
      // Written to TOML only for rough particles (collision.beta > -1), so a
      // smooth scene's text is what it was before the key existed.
      {.key = "system.inertia", .type = KeyType::kFloat, .need = KeyNeed::kOptional,
       .help = "moment of inertia of rough particles (collision.beta > -1) per m a^2, a the radius: 0.4 a uniform "
               "sphere, up to 2/3 a thin shell; 0.5 a uniform disk, up to 1 a ring; absent: the uniform one",
       .lo = 0, .hi = 1, .lo_open = true, .models = {M::kElastic, M::kInelastic},
       .set = [](Scene& s, const SceneValue& v) { s.inertia = std::get<double>(v); },
       .toml = [](const Scene& s) { return s.rough() ? toml_float(s.particle_inertia()) : std::string(); }},
      {.key = "collision.model", .type = KeyType::kString, .need = KeyNeed::kDefault, .help = model_help(),
       .choices = model_names(),
       .set = [](Scene& s, const SceneValue& v) { s.model = choice<CollisionModel>(key_row("collision.model"), v); },
       .toml = [](const Scene& s) { return toml_string(s.model_name()); }},
      // The [driving] table: absent, the gas cools freely (and its scene text
      // is what it was before the table existed).
      {.key = "driving.power", .type = KeyType::kFloat, .need = KeyNeed::kOptional,
       .help = "energy injected per particle per unit time by white-noise kicks that keep the total momentum, in "
               "units of the initial temperature T0 per initial collision time; absent: no driving, the gas "
               "cools freely",
       .lo = 0, .lo_open = true, .models = {M::kElastic, M::kInelastic, M::kViscoelastic},
       .set = [](Scene& s, const SceneValue& v) { s.driving_power = std::get<double>(v); },
       .toml = [](const Scene& s) { return s.driving_power ? toml_float(*s.driving_power) : std::string(); }},
      {.key = "driving.period", .type = KeyType::kFloat, .need = KeyNeed::kOptional,
       .help = "interval between kicks, in mean collision times at the gas's temperature (smaller: closer to the "
               "continuous thermostat, and slower); absent: 0.5",
       .lo = 0.01, .hi = 10, .models = {M::kElastic, M::kInelastic, M::kViscoelastic},
       .set = [](Scene& s, const SceneValue& v) { s.driving_period = std::get<double>(v); },
       .toml = [](const Scene& s) { return s.driving_power ? toml_float(s.driving_period) : std::string(); }},
      {.key = "run.t_end", .type = KeyType::kFloat, .need = KeyNeed::kRequired,
       .help = "simulated time to stop at, in initial mean collision times", .lo = 0, .lo_open = true,
       .set = [](Scene& s, const SceneValue& v) { s.t_end = std::get<double>(v); },
       .toml = [](const Scene& s) { return toml_float(s.t_end); }},
      {.key = "output.observables_per_decade", .type = KeyType::kInteger, .need = KeyNeed::kDefault,
       .help = "observables recorded per decade of time", .lo = 1, .hi = double(kMaxIndex32),
       .set = [](Scene& s, const SceneValue& v) { s.observables_per_decade = int(std::get<std::int64_t>(v)); },
       .toml = [](const Scene& s) { return std::to_string(s.observables_per_decade); }},
      {.key = "output.dumps_per_decade", .type = KeyType::kInteger, .need = KeyNeed::kDefault,
       .help = "trajectory dumps per decade of time", .lo = 1, .hi = double(kMaxIndex32),
       .set = [](Scene& s, const SceneValue& v) { s.dumps_per_decade = int(std::get<std::int64_t>(v)); },
       .toml = [](const Scene& s) { return std::to_string(s.dumps_per_decade); }},
      {.key = "output.t_min", .type = KeyType::kFloat, .need = KeyNeed::kDefault,
       .help = "first time of the log-spaced grids", .lo = 0, .lo_open = true,
       .set = [](Scene& s, const SceneValue& v) { s.t_min = std::get<double>(v); },
       .toml = [](const Scene& s) { return toml_float(s.t_min); }},
      {.key = "output.dump_times", .type = KeyType::kFloatArray, .need = KeyNeed::kDefault,
       .help = "extra dump times, e.g. [5, 10, 2000]", .lo = 0,
       .set = [](Scene& s, const SceneValue& v) { s.dump_times = std::get<std::vector<double>>(v); },
       .toml =
           [](const Scene& s) {
             std::string t = "[";
             for (std::size_t i = 0; i < s.dump_times.size(); ++i) t += (i ? ", " : "") + toml_float(s.dump_times[i]);
             return t + "]";
           }},
  });
  return keys;
}

namespace {

const SceneKey& key_row(const char* name) {
  for (const auto& k : scene_keys())
    if (std::string(k.key) == name) return k;
  throw std::logic_error(std::string("no scene key ") + name);
}

bool used_by(const SceneKey& k, CollisionModel m) {
  return k.models.empty() || std::find(k.models.begin(), k.models.end(), m) != k.models.end();
}
bool used_by(const SceneKey& k, InitialPositions i) {
  return k.inits.empty() || std::find(k.inits.begin(), k.inits.end(), i) != k.inits.end();
}
bool used_by(const SceneKey& k, const Scene& s) { return used_by(k, s.model) && used_by(k, s.init); }

// "\"random\" or \"fcc\"": the starts that use a key.
std::string init_names(const SceneKey& k) {
  std::string out;
  for (I i : k.inits) out += std::string(out.empty() ? "" : " or ") + "\"" + kInitNames[int(i)] + "\"";
  return out;
}

// "in (0, 1]", ">= 0", "" (no bound).
std::string range_text(const SceneKey& k) {
  const bool lo = std::isfinite(k.lo), hi = std::isfinite(k.hi);
  if (lo && hi)
    return std::string("in ") + (k.lo_open ? "(" : "[") + format_number(k.lo) + ", " + format_number(k.hi) +
           (k.hi_open ? ")" : "]");
  if (lo) return (k.lo_open ? "> " : ">= ") + format_number(k.lo);
  if (hi) return (k.hi_open ? "< " : "<= ") + format_number(k.hi);
  return "";
}

const char* type_name(KeyType t) {
  switch (t) {
    case KeyType::kInteger: return "integer";
    case KeyType::kFloat: return "float";
    case KeyType::kString: return "string";
    case KeyType::kFloatArray: return "array of floats";
  }
  return "?";
}

}  // namespace

std::string scene_keys_help() {
  std::string out;
  for (const auto& k : scene_keys()) {
    std::string facts = type_name(k.type);
    const std::string range = k.type == KeyType::kString ? "" : range_text(k);
    if (!range.empty()) facts += ", " + range;
    if (k.need == KeyNeed::kRequired) facts += ", required";
    if (k.need == KeyNeed::kDefault) facts += ", default " + k.toml(Scene{});
    if (k.need == KeyNeed::kOptional) facts += ", optional";
    std::string models;
    for (M m : k.models) models += std::string(models.empty() ? "" : ", ") + model_name(m);
    if (!models.empty()) facts += "; model " + models;
    if (!k.inits.empty()) facts += "; init " + init_names(k);
    out += std::string("  ") + k.key + " (" + facts + "): " + k.help + "\n";
  }
  // Not a key row: an array of tables (parse_species).
  out += "  [[species]] (array of tables, optional; every model): a mixture of sizes and masses, one "
         "table per species (at most " + std::to_string(kMaxSpecies) + "): fraction (its share of N; the fractions "
         "add up to 1), diameter, mass (default diameter^d), in the units of the equal particles (diameter 1, mass "
         "1); absent: equal unit particles\n";
  return out;
}

bool key_changeable_on_resume(const std::string& key) {
  return key.rfind("run.", 0) == 0 || key.rfind("output.", 0) == 0;
}

namespace {

std::string did_you_mean(const std::string& key) {
  std::vector<std::string> keys;
  for (const auto& k : scene_keys()) keys.emplace_back(k.key);
  return coolgas::did_you_mean(key, keys);
}

// Flattens nested tables into dotted keys: {"system.N": value, ...}.
void flatten(const toml::value& v, const std::string& prefix, std::map<std::string, toml::value>& out) {
  if (v.is_table()) {
    for (const auto& [k, sub] : v.as_table()) flatten(sub, prefix.empty() ? k : prefix + "." + k, out);
  } else {
    out[prefix] = v;
  }
}

// What check_parsable needs of a text before toml11 sees it, in one pass
// outside strings and comments: the deepest nesting of brackets and braces
// (toml11 parses them recursively, so a deep text would overflow its stack)
// and the longest array with the key it is given to (toml11 takes time
// quadratic in the length of a line: 10^5 values on one line cost ~15 s, in
// which no signal is looked at).
struct TextShape {
  int deepest = 0;
  std::size_t longest = 0;  // values in the longest array (commas + 1)
  std::string longest_key;  // "table.key" it is given to, as written
};

std::string trimmed(const std::string& text, std::size_t from, std::size_t to) {
  while (from < to && std::isspace(static_cast<unsigned char>(text[from]))) ++from;
  while (to > from && std::isspace(static_cast<unsigned char>(text[to - 1]))) --to;
  return text.substr(from, to - from);
}

// `value`: the text is one value (of --set), never a table header.
TextShape text_shape(const std::string& text, bool value) {
  TextShape shape;
  int depth = 0;
  char quote = 0;
  bool comment = false;
  std::size_t line = 0, values = 0;  // where the current line starts; values of the array open at depth 0
  std::string table, key;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '\n' && !quote) line = i + 1;
    if (comment) {
      comment = c != '\n';
    } else if (quote) {
      if (c == '\\' && quote == '"') ++i;
      else if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '#') {
      comment = true;
    } else if (c == '[' || c == '{') {
      if (depth == 0 && !value && trimmed(text, line, i).empty()) {  // a table header: [name]
        const std::size_t end = text.find(']', i);
        table = trimmed(text, i + 1, end == std::string::npos ? text.size() : end);
      } else if (depth == 0) {  // a value: key = [...]
        const std::size_t eq = text.rfind('=', i);
        const std::string k = eq != std::string::npos && eq >= line ? trimmed(text, line, eq) : "";
        key = table.empty() || k.empty() ? k : table + "." + k;
        values = 1;
      }
      shape.deepest = std::max(shape.deepest, ++depth);
    } else if (c == ']' || c == '}') {
      depth = std::max(0, depth - 1);
      if (depth == 0 && values > shape.longest) shape.longest = values, shape.longest_key = key;
      if (depth == 0) values = 0;
    } else if (c == ',' && depth > 0 && values > 0) {
      ++values;
    }
  }
  return shape;
}

// `value_key`: the key a --set value is given to (its text holds no key).
void check_parsable(const std::string& text, const std::string& source, const std::string& value_key = "") {
  if (text.size() > kMaxSceneBytes)
    throw InputError(source + ": the scene is " + std::to_string(text.size()) + " bytes; the limit is " +
                     std::to_string(kMaxSceneBytes) + " (a scene is a few lines)");
  const TextShape shape = text_shape(text, !value_key.empty());
  if (shape.deepest > kMaxSceneNesting)
    throw InputError(source + ": arrays or tables nested " + std::to_string(shape.deepest) + " deep; the limit is " +
                     std::to_string(kMaxSceneNesting));
  if (double(shape.longest) > kMaxDumps) {
    const std::string key = value_key.empty() ? shape.longest_key : value_key;
    throw InputError(source + ": " + (key.empty() ? std::string("an array") : shown(key)) + " holds " +
                     std::to_string(shape.longest) + " values; the limit is " + std::to_string(int(kMaxDumps)) +
                     " (a run writes at most 1e4 dumps)");
  }
}

toml::value parse_toml(const std::string& text, const std::string& source) {
  check_parsable(text, source);
  std::istringstream in(text);
  try {
    return toml::parse(in, source);
  } catch (const std::exception& e) {
    throw InputError(source + ": not valid TOML: " + one_line(e.what()));
  }
}

// "key=value" -> (key, value), the value parsed as TOML, else as a string.
std::pair<std::string, toml::value> parse_override(const std::string& kv) {
  const auto eq = kv.find('=');
  if (eq == std::string::npos || eq == 0)
    throw InputError("--set '" + shown(kv) + "': expected key=value, e.g. --set collision.r0=0.1");
  const std::string key = kv.substr(0, eq), value = kv.substr(eq + 1);
  check_parsable(value, "--set " + shown(key), key);
  std::istringstream in("v = " + value);
  try {
    return {key, toml::find(toml::parse(in, "--set"), "v")};
  } catch (const std::exception&) {
    return {key, toml::value(value)};
  }
}

std::string shown_toml(const toml::value& v) { return shown(toml::format(v)); }

// A number as the key's type: integers also from floats that are exact integers (1e4).
std::int64_t to_integer(const std::string& key, const toml::value& v) {
  if (v.is_integer()) return v.as_integer();
  if (v.is_floating()) {
    const double x = v.as_floating();
    if (x == std::floor(x) && std::fabs(x) < 0x1p63) return std::int64_t(x);
  }
  throw InputError(key + " must be an integer, got " + shown_toml(v));
}

double to_float(const std::string& key, const toml::value& v) {
  if (v.is_floating()) {
    // The TOML parser reads a literal beyond a double's range (1e400) as the
    // largest double, not as inf: refused as the overflow it is.
    const double x = v.as_floating();
    if (std::fabs(x) == std::numeric_limits<double>::max())
      throw InputError(key + " holds a number beyond a double's range (read as " + shown_toml(v) +
                       "; 1e400 overflows); give a finite number");
    return x;
  }
  if (v.is_integer()) return double(v.as_integer());
  throw InputError(key + " must be a number, got " + shown_toml(v));
}

SceneValue to_value(const SceneKey& k, const toml::value& v) {
  switch (k.type) {
    case KeyType::kInteger: return to_integer(k.key, v);
    case KeyType::kFloat: return to_float(k.key, v);
    case KeyType::kString:
      if (v.is_string()) return v.as_string();
      throw InputError(std::string(k.key) + " must be a string, got " + shown_toml(v));
    case KeyType::kFloatArray: {
      if (!v.is_array()) throw InputError(std::string(k.key) + " must be an array of numbers, e.g. [5, 10]");
      std::vector<double> xs;
      for (const auto& x : v.as_array()) xs.push_back(to_float(k.key, x));
      return xs;
    }
  }
  return {};
}

[[noreturn]] void out_of_range(const std::string& key, double value, const std::string& allowed) {
  throw InputError(key + " = " + format_number(value) + " is out of range: " + allowed);
}

void check_number(const SceneKey& k, double x) {
  const bool ok = std::isfinite(x) && (k.lo_open ? x > k.lo : x >= k.lo) && (k.hi_open ? x < k.hi : x <= k.hi);
  if (ok) return;
  const std::string range = range_text(k);
  out_of_range(k.key, x, range.empty() ? "must be a finite number" : "must be a finite number " + range);
}

void check_value(const SceneKey& k, const SceneValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) {
    // Compared as given: a value beyond the range is never wrapped or rounded into it.
    if ((std::isfinite(k.lo) && double(*i) < k.lo) || (std::isfinite(k.hi) && double(*i) > k.hi))
      throw InputError(std::string(k.key) + " = " + std::to_string(*i) + " is out of range: must be " + range_text(k));
  } else if (const auto* x = std::get_if<double>(&v)) {
    check_number(k, *x);
  } else if (const auto* xs = std::get_if<std::vector<double>>(&v)) {
    for (double x : *xs) check_number(k, x);
  } else if (const auto* str = std::get_if<std::string>(&v)) {
    if (k.choices.empty()) {  // a free text, such as a path
      if (str->empty()) throw InputError(std::string(k.key) + " is empty; give " + k.help);
      return;
    }
    if (std::find(k.choices.begin(), k.choices.end(), *str) != k.choices.end()) return;
    std::string allowed;
    for (std::size_t i = 0; i < k.choices.size(); ++i)
      allowed += std::string(i == 0 ? "" : i + 1 == k.choices.size() ? " or " : ", ") + "\"" + k.choices[i] + "\"";
    throw InputError(std::string(k.key) + " = \"" + shown(*str) + "\" is not known: use " + allowed);
  }
}

// A cost in three significant digits: "3.3e+05".
std::string about(double x) {
  std::ostringstream s;
  s.precision(3);
  s << x;
  return s.str();
}

// Points of the log grid 10^(k/per_decade) in [t_min, t_end], about.
double grid_points(const Scene& s, int per_decade) {
  return std::max(0.0, double(per_decade) * std::log10(s.t_end / s.t_min)) + 1;
}

// The key(s) a refused number of dumps comes from: the log grid's density,
// the explicit list, or both, whichever holds most of them.
std::string dumps_blame(const Scene& s, double extra) {
  const std::string grid = "output.dumps_per_decade = " + std::to_string(s.dumps_per_decade) + " from t = " +
                           format_number(s.t_min) + " to " + format_number(s.t_end);
  const std::string list = "output.dump_times with " + format_number(extra) + " times";
  const double from_grid = grid_points(s, s.dumps_per_decade);
  if (extra > kMaxDumps / 2 && from_grid > kMaxDumps / 2) return grid + " and " + list;
  return extra > from_grid ? list : grid;
}

}  // namespace

void check_scene_size(const Scene& s) {
  const std::string box = check_box_fits_grid(s.L, s.largest_diameter());
  if (!box.empty()) throw InputError(box);
  check_scene_cost(s, usable_memory_bytes());
}

void check_scene_cost(const Scene& s, double memory_bytes) {
  const double n = double(s.N), cells = s.geometry().grid_cells(s.L);
  const double bytes = n * kBytesPerParticle + cells * kBytesPerCell;
  if (n >= kMaxParticles)
    throw InputError("system.N = " + format_number(n) + " would need about " + bytes_text(n * kBytesPerParticle) +
                     " of memory; the limit is N < 2^31 (32-bit particle ids)");
  if (cells > kMaxCells)
    throw InputError("a box of side L = " + format_number(s.L) + " needs a cell grid of " + about(cells) +
                     " cells of one diameter" +
                     (std::isfinite(cells) ? " (" + bytes_text(cells * kBytesPerCell) + ")" : "") +
                     "; the limit is 2^31 cells (" + s.geometry().grid_limit() + "; raise phi or N)");
  if (bytes > memory_bytes)
    throw InputError("the scene needs about " + bytes_text(bytes) + " of memory (" + format_number(n) +
                     " particles, " + format_number(kBytesPerParticle) + " B each, and " + about(cells) +
                     " grid cells, " + format_number(kBytesPerCell) + " B each); the memory available is " +
                     bytes_text(memory_bytes));
  const double equilibration = n * s.equilibrate / 2;
  if (equilibration > kMaxEquilibrationCollisions)
    throw InputError("system.equilibrate = " + format_number(s.equilibrate) + " with N = " + format_number(n) +
                     " means about " + about(equilibration) +
                     " collisions before t = 0; the limit is 1e12 (about 3 weeks)");
  const double extra = double(s.dump_times.size());
  const double dumps = grid_points(s, s.dumps_per_decade) + extra;
  if (dumps > kMaxDumps)
    throw InputError(dumps_blame(s, extra) + " means about " + about(dumps) + " dumps (" +
                     bytes_text(dumps * n * 60) + "); the limit is 1e4 dumps");
  const double rows = grid_points(s, s.observables_per_decade) + grid_points(s, s.dumps_per_decade) + extra;
  if (rows > kMaxObservableRows)
    throw InputError("output.observables_per_decade = " + std::to_string(s.observables_per_decade) + " from t = " +
                     format_number(s.t_min) + " to " + format_number(s.t_end) + " means about " + about(rows) +
                     " rows of observables; the limit is 1e5");
}

namespace {

using KeyValues = std::map<std::string, toml::value>;

void check_species_counts(const Scene& s);

// sum x_k diameter_k^d: the unit particles one particle of the mixture covers, on average.
double measure_per_particle(const Scene& s) {
  double m = 0;
  for (const Species& k : s.species) m += k.fraction * s.geometry().power(k.diameter);
  return m;
}

// Which two of N, L, phi define the box: the overridden ones first, then the
// scene's own in the order phi, N, L (the density is the physics, N the size).
std::vector<std::string> size_keys(const KeyValues& kv, const std::set<std::string>& overridden) {
  std::vector<std::string> keys;
  for (const char* k : {"system.phi", "system.N", "system.L"})
    if (overridden.count(k)) keys.push_back(k);
  if (keys.size() == 1)
    for (const char* k : {"system.phi", "system.N", "system.L"})
      if (kv.count(k) && keys.size() < 2 && keys[0] != k) keys.push_back(k);
  if (keys.empty())
    for (const char* k : {"system.phi", "system.N", "system.L"})
      if (kv.count(k)) keys.push_back(k);
  return keys;
}

// The size key the scene gave that an override pushed out of the two that
// define the box, if its value changed: said, so a --set of N never changes
// L (or phi) without a word.
std::string size_note(const Scene& given, const Scene& s, const std::vector<std::string>& keys, const KeyValues& kv,
                      const std::set<std::string>& overridden) {
  const struct {
    const char* key;
    double was, is;
  } sizes[] = {{"system.N", double(given.N), double(s.N)}, {"system.L", given.L, s.L}, {"system.phi", given.phi, s.phi}};
  for (const auto& z : sizes) {
    if (!kv.count(z.key) || overridden.count(z.key) || std::find(keys.begin(), keys.end(), z.key) != keys.end())
      continue;
    if (std::fabs(z.is - z.was) <= 1e-9 * std::fabs(z.was)) return "";
    const auto named = [&](const std::string& k) { return k + (overridden.count(k) ? " (--set)" : " (the scene's)"); };
    return std::string(z.key) + " = " + format_number(z.is) + ", not the scene's " + format_number(z.was) +
           ": the box follows " + named(keys[0]) + " and " + named(keys[1]) + "; --set " + z.key + " too to keep it";
  }
  return "";
}

void set_size(Scene& s, const KeyValues& kv, const std::set<std::string>& overridden) {
  // A start from a file takes its size from the file, and those of N, L,
  // phi the scene gives are checked against it (simulate/start/file_start.h).
  if (s.init == InitialPositions::kFile) return;
  const auto keys = size_keys(kv, overridden);
  if (keys.size() < 2) throw InputError("the scene must give two of system.N, system.L and system.phi");
  const Scene given = s;
  auto has = [&](const char* k) { return std::find(keys.begin(), keys.end(), k) != keys.end(); };
  const bool hasN = has("system.N"), hasL = has("system.L"), hasPhi = has("system.phi");
  if (!hasN) {
    double n = s.geometry().particles_at(s.phi, s.L);
    if (s.mixture()) n /= measure_per_particle(s);
    if (!(n < kMaxParticles))
      throw InputError("system.phi = " + format_number(s.phi) + " in a box of side L = " + format_number(s.L) +
                       " means N = " + format_number(n) + " particles; the limit is N < 2^31 (32-bit ids)");
    s.N = std::llround(n);
  }
  if (s.N < 2) out_of_range("system.N", double(s.N), "need at least 2 particles");
  if (s.mixture()) check_species_counts(s);
  if (!hasL) s.L = s.geometry().box_side_for(s.unit_particles(), s.phi);
  const double phi_of = s.geometry().covered_fraction(s.unit_particles(), s.L);
  if (hasN && hasL && hasPhi && std::fabs(phi_of - s.phi) > 1e-9 * s.phi)
    throw InputError("system.N, system.L and system.phi disagree: " +
                     std::string(s.geometry().covered_fraction_formula()) +
                     " = " + format_number(phi_of) +
                     " but phi = " + format_number(s.phi) + "; give only two of them");
  s.phi = phi_of;
  s.size_note = size_note(given, s, keys, kv, overridden);
}

// phi computed from N and L lands a few ulps from the phi the scene gave
// (0.45 for 20 000 disks comes back as 0.4500000000000001): a limit is
// exceeded only beyond that round-off.
bool exceeds(double phi, double limit) { return phi > limit * (1 + 1e-12); }

}  // namespace

std::string check_close_packing(const Scene& s) {
  const Geometry g = s.geometry();
  if (s.phi < g.close_packing()) return "";
  return std::string("unit ") + g.particles() + " (system.dimension = " + std::to_string(g.d()) + ") cover at most " +
         format_number(g.close_packing()) + " of the " + g.box() + " (close packing), where none can move; need phi below it";
}

namespace {

// What 1D does not offer, each refused with its own line. Rods cover the
// whole ring at phi = 1; below it the exact equilibrium placement
// (simulate/start/rod_placement.h) reaches any density.
void check_rods(const Scene& s) {
  if (s.init == InitialPositions::kFcc)
    throw InputError("system.init = \"fcc\" is a 3D lattice; in system.dimension = 1 use \"random\" (any phi < 1)");
  if (!(s.phi < 1))
    out_of_range("system.phi", s.phi,
                 "unit rods (system.dimension = 1) cover the ring of length L = " + format_number(s.L) +
                     " at N = L; need N < L");
}

// What 2D does not offer, each refused with its own line.
void check_dimension(const Scene& s) {
  if (s.dimension == 1) return check_rods(s);
  const std::string close = check_close_packing(s);
  if (!close.empty()) out_of_range("system.phi", s.phi, close);
  if (s.dimension == 3) return;
  if (s.init == InitialPositions::kFcc)
    throw InputError("system.init = \"fcc\" is a 3D lattice; in system.dimension = 2 use \"random\" (phi <= 0.45)");
  if (s.init == InitialPositions::kRandom && exceeds(s.phi, kMaxRandomPhi2D))
    out_of_range("system.phi", s.phi,
                 "random sequential addition of disks (system.dimension = 2) reaches phi <= 0.45 here");
}

// Limits that involve more than one key.
void check_relations(const Scene& s) {
  check_dimension(s);
  if (s.dimension != 3) return;
  if (s.init == InitialPositions::kRandom && exceeds(s.phi, kMaxRandomPhi))
    out_of_range("system.phi", s.phi,
                 "random sequential addition reaches phi <= 0.36; use system.init = \"fcc\" (up to 0.74)");
  if (s.init == InitialPositions::kFcc && exceeds(s.phi, kMaxFccPhi))
    out_of_range("system.phi", s.phi, "an FCC lattice of unit spheres holds phi <= 0.7404");
}

// Each model takes only its own collision.* keys, and each start its own
// system.* keys, so a typo in the model name cannot silently drop a
// parameter; a key at its default value changes nothing.
void check_unused_keys(const Scene& s, const KeyValues& kv) {
  const Scene defaults;
  for (const auto& k : scene_keys()) {
    if (!kv.count(k.key) || used_by(k, s) || k.toml(s) == k.toml(defaults)) continue;
    if (!used_by(k, s.init))
      throw InputError(std::string(k.key) + " is set but system.init = \"" + kInitNames[int(s.init)] +
                       "\" does not use it; remove it, or set init = " + init_names(k));
    std::string users;
    for (M m : k.models) users += std::string(users.empty() ? "" : " or ") + "\"" + model_name(m) + "\"";
    throw InputError(std::string(k.key) + " is set but collision.model = \"" + s.model_name() +
                     "\" does not use it; remove it, or set model = " + users);
  }
}

// Keys without a default that the scene's model uses must be given.
void check_required(const Scene& s, const KeyValues& kv) {
  for (const auto& k : scene_keys()) {
    if (k.need != KeyNeed::kRequired || kv.count(k.key) || !used_by(k, s)) continue;
    const std::string help = k.help, what = help.substr(0, help.find(','));
    const std::string model = !k.inits.empty() ? " for system.init = \"" + std::string(kInitNames[int(s.init)]) + "\""
                              : k.models.empty() ? "" : " for collision.model = \"" + s.model_name() + "\"";
    throw InputError("the scene must give " + std::string(k.key) + model + " (" + what + ")");
  }
}

// The kicks' interval means nothing without their power.
void check_driving(const Scene& s, const KeyValues& kv) {
  if (kv.count("driving.period") && !s.driving_power)
    throw InputError("driving.period is set but driving.power is not; give driving.power (the energy injected per "
                     "particle per unit time) or remove driving.period");
}

// Spins mean something only for rough particles that can turn: disks and
// spheres, whose inertia a mass distribution of their shape allows.
void check_rough(const Scene& s, const KeyValues& kv) {
  if (!s.rough()) {
    if (kv.count("system.inertia"))
      throw InputError("system.inertia is set but the particles are smooth (collision.beta = -1: their spins never "
                       "change); set collision.beta in (-1, 1] or remove system.inertia");
    return;
  }
  const Geometry g = s.geometry();
  if (g.rotational_axes() == 0)
    out_of_range("collision.beta", s.parameter("beta"),
                 std::string("rods (system.dimension = 1) cannot spin, their contacts have no tangent; need beta = "
                             "-1, or system.dimension = 2 or 3"));
  if (s.particle_inertia() > g.largest_inertia())
    out_of_range("system.inertia", s.particle_inertia(),
                 std::string("the moment of inertia of ") + g.particles() + " per m a^2 is at most " +
                     format_number(g.largest_inertia()) + " (all the mass on the rim); need (0, " +
                     format_number(g.largest_inertia()) + "]");
}

// ---- [[species]]: a mixture of sizes and masses.

// The keys of a [[species]] table.
const char* const kSpeciesKeys[] = {"fraction", "diameter", "mass"};

// "[[species]] 2" for messages: tables counted from 1, as a reader counts them.
std::string species_name(std::size_t k) { return "[[species]] " + std::to_string(k + 1); }

double species_number(const toml::value& v, const std::string& key, double lo, bool lo_open, double hi) {
  const double x = to_float(key, v);
  if (!(std::isfinite(x) && (lo_open ? x > lo : x >= lo) && x <= hi))
    out_of_range(key, x, std::string("must be a finite number ") + (lo_open ? "> " : ">= ") + format_number(lo) +
                             (std::isfinite(hi) ? " and <= " + format_number(hi) : ""));
  return x;
}

Species parse_one_species(const toml::value& table, std::size_t k) {
  const std::string name = species_name(k);
  if (!table.is_table())
    throw InputError(name + " is not a table; write [[species]] with fraction = ..., diameter = ... below it");
  Species out;
  for (const auto& [key, value] : table.as_table()) {
    const std::string full = name + " " + key;
    if (key == "fraction") out.fraction = species_number(value, full, 0, true, 1);
    else if (key == "diameter") out.diameter = species_number(value, full, 0, true, kInf);
    else if (key == "mass") out.mass = species_number(value, full, 0, true, kInf);
    else
      throw InputError("unknown key '" + shown(key) + "' in " + name +
                       coolgas::did_you_mean(key, {std::begin(kSpeciesKeys), std::end(kSpeciesKeys)}) +
                       " (a species has fraction, diameter and mass)");
  }
  for (const char* required : {"fraction", "diameter"})
    if (!table.as_table().count(required))
      throw InputError(name + " must give " + required +
                       (std::string(required) == "fraction" ? " (its share of the number of particles)"
                                                            : " (its particles' diameter)"));
  return out;
}

// The [[species]] tables (an array of tables, or of inline tables from --set):
// each one well formed, at most kMaxSpecies, fractions adding up to 1.
std::vector<Species> parse_species(const toml::value& v) {
  if (!v.is_array() || v.as_array().empty())
    throw InputError("species must be an array of tables: write one [[species]] table per species, with "
                     "fraction = ... and diameter = ...");
  const auto& tables = v.as_array();
  if (tables.size() > std::size_t(kMaxSpecies))
    throw InputError("the scene lists " + std::to_string(tables.size()) + " [[species]]; the limit is " +
                     std::to_string(kMaxSpecies));
  std::vector<Species> out;
  double sum = 0;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    out.push_back(parse_one_species(tables[k], k));
    sum += out.back().fraction;
  }
  if (std::fabs(sum - 1.0) > 1e-9)
    throw InputError("the [[species]] fractions add up to " + format_number(sum) +
                     ", not 1; each is a share of the number of particles");
  return out;
}

// What a mixture does not offer, each refused with its own line.
void check_mixture(const Scene& s, const KeyValues& kv) {
  if (!s.mixture()) return;
  if (s.rough())
    throw InputError("[[species]] is set with rough particles (collision.beta > -1): a rough mixture is not "
                     "offered; remove collision.beta or [[species]]");
  if (s.driving_power)
    throw InputError("[[species]] is set with [driving]: a driven mixture is not offered; remove [driving] or "
                     "[[species]]");
  if (s.init == InitialPositions::kFcc)
    throw InputError("system.init = \"fcc\" is a lattice of equal spheres; a mixture ([[species]]) starts from "
                     "\"random\"");
  if (s.init == InitialPositions::kFile || kv.count("system.from"))
    throw InputError("system.init = \"file\" with [[species]] is not offered (a file's particles carry no species "
                     "table); start a mixture from \"random\"");
}

// Every species gets a particle.
void check_species_counts(const Scene& s) {
  const auto counts = s.species_counts();
  for (std::size_t k = 0; k < counts.size(); ++k)
    if (counts[k] == 0)
      throw InputError(species_name(k) + " has fraction = " + format_number(s.species[k].fraction) +
                       ", no particle of N = " + std::to_string(s.N) + "; raise N or its fraction");
}

void check_mixture_density(const Scene& s) {
  if (!s.mixture() || s.dimension == 1) return;  // rods are placed exactly at any phi < 1
  double limit = kMaxMixturePhi;
  if (s.dimension == 2) limit = kMaxMixturePhi2D;
  if (exceeds(s.phi, limit))
    out_of_range("system.phi", s.phi,
                 "a mixture ([[species]]) of " + std::string(s.geometry().particles()) +
                     " is placed by plain random trials, which reach phi <= " + format_number(limit) + " here");
}

Scene build_scene(const KeyValues& kv, const std::set<std::string>& overridden) {
  Scene s;
  for (const auto& k : scene_keys()) {
    const auto it = kv.find(k.key);
    if (it == kv.end()) continue;
    const SceneValue v = to_value(k, it->second);
    check_value(k, v);
    k.set(s, v);
  }
  if (const auto it = kv.find(kSpeciesKey); it != kv.end()) s.species = parse_species(it->second);
  check_unused_keys(s, kv);
  check_mixture(s, kv);
  check_driving(s, kv);
  check_rough(s, kv);
  check_required(s, kv);
  set_size(s, kv, overridden);
  check_relations(s);
  check_mixture_density(s);
  // A start from a file knows its size here only when the scene states it
  // (a resumed run's effective scene); else once the file is read.
  if (s.init != InitialPositions::kFile || (s.N > 0 && s.L > 0)) check_scene_size(s);
  return s;
}

}  // namespace

Scene parse_scene(const std::string& toml_text, const std::string& source, const std::vector<std::string>& overrides) {
  KeyValues kv;
  flatten(parse_toml(toml_text, source), "", kv);
  std::set<std::string> overridden;
  for (const auto& o : overrides) {
    auto [key, value] = parse_override(o);
    kv[key] = value;
    overridden.insert(key);
  }
  for (const auto& entry : kv) {
    const std::string& key = entry.first;  // a name, not a binding: lambdas capture it (clang before 16 cannot)
    const bool known = key == kSpeciesKey || std::any_of(scene_keys().begin(), scene_keys().end(),
                                                         [&](const SceneKey& k) { return key == k.key; });
    if (!known) throw InputError("unknown scene key '" + shown(key) + "'" + did_you_mean(key));
  }
  return build_scene(kv, overridden);
}

std::string physics_toml(const Scene& s) {
  Scene p;
  p.species = s.species;
  for (const SceneKey& k : scene_keys()) {
    const std::string value = k.toml(s);
    if (key_changeable_on_resume(k.key) || value.empty()) continue;
    k.set(p, to_value(k, parse_override(std::string(k.key) + "=" + value).second));
  }
  return p.to_toml();
}

namespace {

const ModelParameter& parameter_row(std::string_view name) {
  if (const ModelParameter* p = find_model_parameter(name)) return *p;
  throw std::logic_error("no model parameter " + std::string(name));
}

}  // namespace

double Scene::parameter(std::string_view name) const {
  const auto it = collision.find(name);
  if (it != collision.end()) return it->second;
  const ModelParameter& p = parameter_row(name);
  if (!p.default_value) throw std::logic_error("the scene gives no collision." + std::string(name));
  return *p.default_value;
}

void Scene::set_parameter(std::string_view name, double value) {
  collision[std::string(parameter_row(name).name)] = value;
}

std::string model_name(CollisionModel m) { return std::string(collision_models().at(std::size_t(m)).name); }

std::string Scene::model_name() const { return coolgas::model_name(model); }

std::string Scene::to_toml() const {
  std::string out = "# coolgas scene: the effective values (file, --set overrides and defaults)\n";
  std::string table;
  for (const auto& k : scene_keys()) {
    const std::string key = k.key, name = key.substr(0, key.find('.'));
    const std::string value = used_by(k, *this) ? k.toml(*this) : "";
    if (value.empty()) continue;  // a table none of whose keys is written ([driving]) is left out
    if (name != table) out += (table.empty() ? "[" : "\n[") + name + "]\n", table = name;
    out += key.substr(key.find('.') + 1) + " = " + value + "\n";
  }
  for (std::size_t k = 0; k < species.size(); ++k)  // written only for a mixture: other scenes' text is as before
    out += "\n[[species]]\nfraction = " + toml_float(species[k].fraction) + "\ndiameter = " +
           toml_float(species[k].diameter) + "\nmass = " + toml_float(species_mass(k)) + "\n";
  return out;
}

double Scene::species_mass(std::size_t k) const {
  return species.at(k).mass.value_or(geometry().mass_of_diameter(species.at(k).diameter));
}

std::vector<std::int64_t> Scene::species_counts() const {
  std::vector<std::int64_t> counts(species.size());
  std::vector<std::pair<double, std::size_t>> remainders;
  std::int64_t given = 0;
  for (std::size_t k = 0; k < species.size(); ++k) {
    const double exact = species[k].fraction * double(N);
    counts[k] = std::int64_t(std::floor(exact));
    given += counts[k];
    remainders.emplace_back(-(exact - std::floor(exact)), k);  // largest first, then the earlier species
  }
  std::sort(remainders.begin(), remainders.end());
  for (std::size_t r = 0; given < N && r < remainders.size(); ++r, ++given) ++counts[remainders[r].second];
  return counts;
}

double Scene::largest_diameter() const {
  double d = species.empty() ? 1.0 : 0.0;
  for (const Species& k : species) d = std::max(d, k.diameter);
  return d;
}

double Scene::unit_particles() const {
  if (species.empty()) return double(N);
  const auto counts = species_counts();
  double sum = 0;
  for (std::size_t k = 0; k < species.size(); ++k) sum += double(counts[k]) * geometry().power(species[k].diameter);
  return sum;
}

}  // namespace coolgas
