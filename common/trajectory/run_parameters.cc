#include "common/trajectory/run_parameters.h"

#include <algorithm>
#include <stdexcept>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/layout.h"

// The table names only the fields a row needs; the others keep their member
// defaults on purpose. GCC 12 warns about that even so.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace coolgas {

bool has_particle_species(const RunParameters& p) { return is_mixture(p) && model_keeps_species(p.model); }

namespace {

using enum ParameterRole;

template <class... F>
struct Overloaded : F... {
  using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;  // clang before 17 deduces no aggregate's arguments

std::string text_of(std::int64_t v) { return std::to_string(v); }
std::string text_of(double v) { return format_number(v); }
std::string text_of(const std::string& v) { return v; }
std::string text_of(const std::vector<double>& v) {  // "0.5,0.5": one per species
  std::string t;
  for (std::size_t k = 0; k < v.size(); ++k) t += (k ? "," : "") + format_number(v[k]);
  return t;
}

// Attributes of the class the member needs; anything else would fail deep in
// HDF5's conversion with a message naming nothing.
H5T_class_t class_of(const ParameterField::Member& m) {
  return std::visit(Overloaded{[](std::int64_t RunParameters::*) { return H5T_INTEGER; },
                               [](std::string RunParameters::*) { return H5T_STRING; },
                               [](auto) { return H5T_FLOAT; }},
                    m);
}

// Whether a file of these parameters holds the field (optional ones: when set).
bool present_for(const RunParameters& p, const ParameterField& f) {
  if (const auto* m = std::get_if<std::optional<double> RunParameters::*>(&f.member)) return (p.**m).has_value();
  if (const auto* m = std::get_if<std::vector<double> RunParameters::*>(&f.member)) return !(p.**m).empty();
  if (!is_model_specific(f)) return true;
  if (!model_uses(p.model, f.name)) return false;
  return !is_optional(f) || p.collision.count(f.name) != 0;  // beta: present when not at its `off` value
}

void read_field_unchecked(hid_t g, const std::string& path, const ParameterField& f, RunParameters& p) {
  const std::string name(f.name);
  if (!h5::has_attr(g, name)) throw InputError(path + ": not a coolgas trajectory: missing /parameters attribute '" + name + "'");
  if (h5::attr_class(g, name) != class_of(f.member))
    throw InputError(path + ": /parameters attribute '" + name + "' has the wrong type (expected " +
                     (class_of(f.member) == H5T_INTEGER ? "an integer" : class_of(f.member) == H5T_STRING ? "a string" : "a float") +
                     ")");
  std::visit(Overloaded{[&](std::int64_t RunParameters::*m) { p.*m = h5::read_attr_int(g, name); },
                        [&](double RunParameters::*m) { p.*m = h5::read_attr_double(g, name); },
                        [&](std::string RunParameters::*m) { p.*m = h5::read_attr_string(g, name); },
                        [&](std::optional<double> RunParameters::*m) { p.*m = h5::read_attr_double(g, name); },
                        [&](std::vector<double> RunParameters::*m) {
                          p.*m = h5::read_attr_doubles(g, name, kMaxFileSpecies);
                        },
                        [&](ModelValue) { p.collision[name] = h5::read_attr_double(g, name); }},
             f.member);
}

// A damaged attribute (its header or value unreadable) is the file's
// problem, named with the field, not an internal error.
void read_field(hid_t g, const std::string& path, const ParameterField& f, RunParameters& p) {
  try {
    read_field_unchecked(g, path, f, p);
  } catch (const h5::Error& e) {
    throw InputError(path + ": /parameters attribute '" + std::string(f.name) + "' cannot be read: the file is damaged" +
                     (e.cause.empty() ? "" : " (" + e.cause + ")"));
  } catch (const h5::Damaged&) {
    throw InputError(path + ": /parameters attribute '" + std::string(f.name) + "' cannot be read: the file is damaged");
  }
}

// N bounds every array a reader allocates: ids are 32-bit.
void check_particle_count(const RunParameters& p, const std::string& path) {
  if (p.N < 1 || p.N > kMaxStoredParticles)
    throw InputError(path + ": /parameters/N = " + std::to_string(p.N) + " is out of range: a trajectory holds 1 to " +
                     std::to_string(kMaxStoredParticles) + " particles (32-bit ids)");
}

}  // namespace

const std::vector<ParameterField>& run_parameter_fields() {
  // The common fields in the order of data-schema/h5md-profile.md, then one
  // per model parameter (collision_models.h); the provenance of the tools'
  // tables lists the kPhysics rows in this order too.
  static const std::vector<ParameterField> fields = [] {
    std::vector<ParameterField> f = {
      {"schema_version", &RunParameters::schema_version, "profile version", kRecord, 1, 1},
      {"program_version", &RunParameters::program_version, "simulator version", kRecord},
      {"scene", &RunParameters::scene_toml, "effective scene (TOML)", kRecord},
      {"seed", &RunParameters::seed, "random seed", kSeed},
      {"N", &RunParameters::N, "number of particles", kPhysics, 1, 1},
      {"L", &RunParameters::L, "box side", kPhysics},
      {"phi", &RunParameters::phi, "volume fraction", kPhysics},
      {"T0", &RunParameters::T0, "initial temperature", kPhysics},
      {"model", &RunParameters::model, "collision model", kPhysics},
    };
    for (const ModelParameter* m : model_parameters())
      f.push_back({m->name, ModelValue{}, m->meaning, kPhysics, m->since});
    f.push_back({"driving_power", &RunParameters::driving_power, "energy injected per particle per unit time",
                 kPhysics, int(kDrivingSchemaVersion), std::nullopt, 0.0});
    f.push_back({"driving_period", &RunParameters::driving_period, "kick interval in mean collision times",
                 kPhysics, int(kDrivingSchemaVersion), std::nullopt, 0.0});
    f.push_back({"inertia", &RunParameters::inertia, "moment of inertia per m a^2 (rough particles)", kPhysics,
                 int(kRoughSchemaVersion), std::nullopt, 0.0});
    f.push_back({"species_fraction", &RunParameters::species_fraction, "each species' share of N (mixtures)",
                 kPhysics, int(kMixtureSchemaVersion), std::nullopt, 0.0});
    f.push_back({"species_diameter", &RunParameters::species_diameter, "each species' diameter (mixtures)", kPhysics,
                 int(kMixtureSchemaVersion), std::nullopt, 0.0});
    f.push_back({"species_mass", &RunParameters::species_mass, "each species' mass (mixtures)", kPhysics,
                 int(kMixtureSchemaVersion), std::nullopt, 0.0});
    return f;
  }();
  return fields;
}

bool is_model_specific(const ParameterField& f) {
  return std::holds_alternative<ModelValue>(f.member);
}

bool is_optional(const ParameterField& f) {
  if (is_model_specific(f)) {
    const ModelParameter* m = find_model_parameter(f.name);
    return m && m->off;
  }
  return std::holds_alternative<std::optional<double> RunParameters::*>(f.member) ||
         std::holds_alternative<std::vector<double> RunParameters::*>(f.member);
}

std::int64_t schema_version_of(const RunParameters& p, std::int64_t model_version) {
  std::int64_t v = model_version;
  if (p.driving_power) v = std::max(v, kDrivingSchemaVersion);
  if (is_rough(p.collision)) v = std::max(v, kRoughSchemaVersion);
  if (is_mixture(p)) v = std::max(v, kMixtureSchemaVersion);
  return v;
}

std::optional<std::string> field_text(const RunParameters& p, const ParameterField& f) {
  return std::visit(Overloaded{[&](ModelValue) -> std::optional<std::string> {
                                 const auto it = p.collision.find(f.name);
                                 if (it == p.collision.end()) return std::nullopt;
                                 return text_of(it->second);
                               },
                               [&](std::optional<double> RunParameters::*m) -> std::optional<std::string> {
                                 if (!(p.*m)) return std::nullopt;
                                 return text_of(*(p.*m));
                               },
                               [&](std::vector<double> RunParameters::*m) -> std::optional<std::string> {
                                 if ((p.*m).empty()) return std::nullopt;
                                 return text_of(p.*m);
                               },
                               [&](auto m) -> std::optional<std::string> { return text_of(p.*m); }},
                    f.member);
}

void write_parameters(hid_t g, const RunParameters& p) {
  if (!find_collision_model(p.model)) throw std::logic_error("writing a run of unknown model '" + p.model + "'");
  for (const ParameterField& f : run_parameter_fields()) {
    const std::string name(f.name);
    const bool want = present_for(p, f);
    std::visit(Overloaded{[&](ModelValue) {
                            const auto it = p.collision.find(name);
                            if (want != (it != p.collision.end()))
                              throw std::logic_error("parameter " + name + (want ? " missing" : " set") +
                                                     " for model " + p.model);
                            if (want) h5::write_attr(g, name, it->second);
                          },
                          [&](std::optional<double> RunParameters::*m) {
                            if (p.*m) h5::write_attr(g, name, *(p.*m));
                          },
                          [&](std::vector<double> RunParameters::*m) {
                            if (!(p.*m).empty()) h5::write_attr(g, name, p.*m);
                          },
                          [&](auto m) { h5::write_attr(g, name, p.*m); }},
               f.member);
  }
}

RunParameters read_parameters(hid_t g, const std::string& path) {
  RunParameters p;
  p.collision.clear();  // the defaults are elastic spheres'; a file says what it has
  for (const ParameterField& f : run_parameter_fields()) {
    if (f.name == "model") {
      read_field(g, path, f, p);
      if (!find_collision_model(p.model))
        throw InputError(path + ": /parameters/model '" + p.model + "' is not known (known: " +
                         collision_model_names() + ")");
      break;
    }
  }
  for (const ParameterField& f : run_parameter_fields()) {
    if (f.name == "model") continue;
    if (is_optional(f) ? h5::has_attr(g, std::string(f.name)) : present_for(p, f)) read_field(g, path, f, p);
  }
  check_particle_count(p, path);
  return p;
}

RunParameters read_file_parameters(hid_t file, const std::string& path) {
  const std::string group(layout::kParameters);
  if (!h5::exists(file, group)) throw InputError(path + ": not a coolgas trajectory: missing " + group);
  h5::Handle g;
  try {
    g = h5::open_group(file, group);
  } catch (const h5::Error& e) {
    throw InputError(path + ": " + group + " cannot be opened: the file is damaged" +
                     (e.cause.empty() ? "" : " (" + e.cause + ")"));
  } catch (const h5::Damaged&) {
    throw InputError(path + ": " + group + " cannot be opened: the file is damaged");
  }
  return read_parameters(g.id(), path);
}

std::optional<std::string> physics_difference(const RunParameters& a, const RunParameters& b) {
  for (const ParameterField& f : run_parameter_fields()) {
    if (f.role != kPhysics) continue;
    const auto x = field_text(a, f), y = field_text(b, f);
    if (x != y) return std::string(f.name) + " = " + x.value_or("(absent)") + " vs " + y.value_or("(absent)");
  }
  return std::nullopt;
}

Provenance physics_provenance(const RunParameters& p) {
  Provenance out;
  for (const ParameterField& f : run_parameter_fields())
    if (f.role == kPhysics)
      if (auto t = field_text(p, f)) out.emplace_back(std::string(f.name), *t);
  return out;
}

}  // namespace coolgas
