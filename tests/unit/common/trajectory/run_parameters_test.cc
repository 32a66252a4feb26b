// The run-parameter and collision-model tables (common/trajectory/
// run_parameters.h, collision_models.h): every field is either compared by
// the ensemble check or listed here as not defining the physics; a file holds
// exactly the table's attributes for its model; "not applicable" is absent.
#include "common/trajectory/run_parameters.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "common/trajectory/collision_models.h"
#include "common/trajectory/h5md_writer.h"
#include "common/trajectory/layout.h"
#include "common/trajectory/run_info.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// The fields that may differ between the runs of one ensemble. Anything
// else in the table must be compared: a new field is either physics or
// added here on purpose.
const std::set<std::string> kNotCompared = {"schema_version", "program_version", "scene", "seed"};

RunParameters params_for(const std::string& model) {
  RunParameters p;
  p.scene_toml = "[system]\nN = 2\n";
  p.seed = 3;
  p.N = 2;
  p.L = 5;
  p.phi = 0.008;
  p.T0 = 0.5;
  p.model = model;
  p.collision.clear();
  if (model_uses(model, "r0")) p.collision["r0"] = model == "elastic" ? 1.0 : 0.5;
  if (model_uses(model, "delta")) p.collision["delta"] = model == "elastic" ? 0.0 : 1e-4;
  if (model_uses(model, "viscoelastic_b")) p.collision["viscoelastic_b"] = 0.1;
  return p;
}

// Changes one field of p, whatever its type.
void perturb(RunParameters& p, const ParameterField& f) {
  std::visit([&](auto m) {
    if constexpr (std::is_same_v<decltype(m), ModelValue>) {
      const auto [it, absent] = p.collision.try_emplace(std::string(f.name), 0.0);  // beta: absent when smooth
      it->second = absent ? 0.5 : 2 * it->second + 1;
    } else {
      using T = std::decay_t<decltype(p.*m)>;
      if constexpr (std::is_same_v<T, std::string>) p.*m += "x";
      else if constexpr (std::is_same_v<T, std::optional<double>>) p.*m = 2 * (p.*m).value_or(0) + 1;
      else if constexpr (std::is_same_v<T, std::vector<double>>) (p.*m).push_back(0.5);  // a species more
      else p.*m = 2 * (p.*m) + 1;
    }
  }, f.member);
}

// A model in whose files the field is present.
std::string model_having(const ParameterField& f) {
  for (const auto& m : collision_models())
    if (!is_model_specific(f) || model_uses(m.name, f.name)) return std::string(m.name);
  return "";
}

TEST(RunParameters, EveryFieldIsComparedOrListedAsNotDefiningThePhysics) {
  std::set<std::string> seen;
  for (const ParameterField& f : run_parameter_fields()) {
    const std::string name(f.name);
    seen.insert(name);
    const std::string model = model_having(f);
    ASSERT_FALSE(model.empty()) << name << " is present in no model's files";
    const RunParameters a = params_for(model);
    RunParameters b = a;
    if (name == "model") b = params_for(model == "elastic" ? "inelastic" : "elastic");
    else perturb(b, f);
    const auto d = physics_difference(a, b);
    if (kNotCompared.count(name)) {
      EXPECT_FALSE(d) << name << " is compared but listed as not defining the physics: " << *d;
      EXPECT_NE(f.role, ParameterRole::kPhysics) << name;
    } else {
      ASSERT_TRUE(d) << name << " differs but the ensemble check does not see it";
      EXPECT_EQ(d->substr(0, name.size() + 3), name + " = ") << *d;
    }
  }
  for (const std::string& n : kNotCompared) EXPECT_TRUE(seen.count(n)) << n << " is listed but not a field";
}

TEST(RunParameters, ViscoelasticRunsWithDifferentBAreDifferentPhysics) {
  RunParameters a = params_for("viscoelastic"), b = a;
  a.collision["viscoelastic_b"] = 0.1;
  b.collision["viscoelastic_b"] = 0.9;
  EXPECT_EQ(physics_difference(a, b), "viscoelastic_b = 0.1 vs 0.9");
  const Provenance p = physics_provenance(a);
  EXPECT_NE(std::find(p.begin(), p.end(), std::pair<std::string, std::string>{"viscoelastic_b", "0.1"}), p.end());
  for (const auto& [k, v] : p) EXPECT_NE(k, "r0") << "viscoelastic spheres have no constant r0";
}

// Which attributes a group holds, by name.
std::set<std::string> attribute_names(hid_t group) {
  H5O_info_t info{};
  EXPECT_GE(H5Oget_info2(group, &info, H5O_INFO_NUM_ATTRS), 0);
  std::set<std::string> names;
  for (hsize_t i = 0; i < info.num_attrs; ++i) {
    char name[256] = {};
    H5Aget_name_by_idx(group, ".", H5_INDEX_CRT_ORDER, H5_ITER_NATIVE, i, name, sizeof name, H5P_DEFAULT);
    names.insert(name);
  }
  return names;
}

// Every model's file, a driven gas's (simulate/engine/driving.h), one of
// rough particles and a mixture's: the driving attributes are there exactly
// when the run is driven, and make its file of schema version 4; beta and
// inertia exactly when the particles are rough (beta > -1), of version 5;
// the species table exactly for a mixture, of version 6.
TEST(RunParameters, EachModelsFileHoldsExactlyItsFieldsAndReadsThemBack) {
  const std::set<std::string> driving = {"driving_power", "driving_period"}, rough = {"beta", "inertia"};
  const std::set<std::string> mixture = {"species_fraction", "species_diameter", "species_mass"};
  for (const CollisionModelSpec& m : collision_models())
    for (const std::string effect : {"", "driven", "rough", "mixture"}) {
      if ((effect == "driven" || effect == "mixture") && m.layout != layout::Layout::kGas) continue;
      if (effect == "rough" && !model_uses(m.name, "beta")) continue;
      const std::string model = std::string(m.name) + (effect.empty() ? "" : "_" + effect);
      const std::string path = test::scratch_dir("run_parameters_" + model) + "/run.h5";
      RunParameters written = params_for(std::string(m.name));
      if (effect == "driven") written.driving_power = 0.3, written.driving_period = 0.5;
      if (effect == "rough") written.collision["beta"] = 0.5, written.inertia = 0.4;
      if (effect == "mixture")
        written.species_fraction = {0.25, 0.75}, written.species_diameter = {1, 0.5},
        written.species_mass = {1, 0.125};
      { H5mdWriter::create(path, written, true, Geometry(3)); }
      h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
      h5::Handle g = h5::open_group(f.id(), std::string(layout::kParameters));
      std::set<std::string> expected;
      for (const ParameterField& field : run_parameter_fields()) {
        const std::string name(field.name);
        if (is_optional(field) ? (effect == "driven" && driving.count(name)) ||
                                     (effect == "rough" && rough.count(name)) ||
                                     (effect == "mixture" && mixture.count(name))
                               : !is_model_specific(field) || model_uses(m.name, field.name))
          expected.insert(name);
      }
      EXPECT_EQ(attribute_names(g.id()), expected) << model;
      EXPECT_EQ(h5::read_attr_int(g.id(), "schema_version"), effect == "driven"    ? kDrivingSchemaVersion
                                                             : effect == "rough"   ? kRoughSchemaVersion
                                                             : effect == "mixture" ? kMixtureSchemaVersion
                                                                                   : m.schema_version)
          << model;
      const RunParameters read = read_parameters(g.id(), path);
      for (const ParameterField& field : run_parameter_fields()) {
        if (field.role == ParameterRole::kRecord) continue;
        EXPECT_EQ(field_text(read, field), field_text(written, field)) << model << " " << field.name;
      }
      EXPECT_EQ(read.scene_toml, written.scene_toml);
    }
}

TEST(RunParameters, NotApplicableIsAbsentNotASentinel) {
  RunParameters p = params_for("viscoelastic");
  p.collision["r0"] = 1.0;  // what version 2 wrote
  const std::string path = test::scratch_dir("run_parameters_sentinel") + "/run.h5";
  EXPECT_THROW(H5mdWriter::create(path, p, true, Geometry(3)), std::logic_error);
  p.collision.erase("r0");
  p.collision.erase("delta");
  EXPECT_THROW(H5mdWriter::create(path, p, true, Geometry(3)), std::logic_error);  // viscoelastic files hold delta
  // A version-2 viscoelastic file carries r0 = 1; it reads as absent.
  {
    H5mdWriter::create(path, params_for("viscoelastic"), true, Geometry(3));
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    h5::Handle g = h5::open_group(f.id(), std::string(layout::kParameters));
    h5::write_attr(g.id(), "r0", 1.0);
    h5::write_attr(g.id(), "schema_version", std::int64_t{2});
  }
  EXPECT_FALSE(read_run_info(path).params.collision.count("r0"));
  { H5mdWriter::create(path, params_for("aggregation"), true, Geometry(3)); }
  const RunParameters agg = read_run_info(path).params;
  EXPECT_FALSE(agg.collision.count("r0"));
  EXPECT_FALSE(agg.collision.count("delta"));
}

TEST(RunParameters, WrongTypeOrUnknownModelIsAnInputErrorNamingTheAttribute) {
  const std::string path = test::scratch_dir("run_parameters_wrong") + "/run.h5";
  { H5mdWriter::create(path, params_for("inelastic"), true, Geometry(3)); }
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    h5::Handle g = h5::open_group(f.id(), std::string(layout::kParameters));
    h5::write_attr(g.id(), "N", std::string("two"));
  }
  try {
    read_run_info(path);
    FAIL() << "a string N was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("attribute 'N' has the wrong type"), std::string::npos) << e.what();
  }
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    h5::Handle g = h5::open_group(f.id(), std::string(layout::kParameters));
    h5::write_attr(g.id(), "model", std::string("sticky"));
  }
  try {
    read_run_info(path);
    FAIL() << "an unknown model was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'sticky' is not known"), std::string::npos) << e.what();
  }
}

TEST(CollisionModels, ParametersAreModelSpecificFieldsAndVersionsAreInTheProfile) {
  std::set<std::string_view> names;
  for (const CollisionModelSpec& m : collision_models()) {
    EXPECT_TRUE(names.insert(m.name).second) << m.name << " twice";
    EXPECT_EQ(find_collision_model(m.name), &m);
    EXPECT_GE(m.schema_version, 1);
    std::vector<const ModelParameter*> listed = m.parameters;
    for (const FixedParameter& f : m.fixed) listed.push_back(f.parameter);
    for (const ModelParameter* mp : listed) {
      const std::string_view p = mp->name;
      const auto& all = model_parameters();
      EXPECT_NE(std::find(all.begin(), all.end(), mp), all.end()) << m.name << " lists " << p << ", not in model_parameters()";
      const auto& fields = run_parameter_fields();
      const auto f = std::find_if(fields.begin(), fields.end(), [&](const ParameterField& x) { return x.name == p; });
      ASSERT_NE(f, fields.end()) << m.name << " lists " << p << ", which is no field";
      EXPECT_TRUE(is_model_specific(*f)) << p;
      // A parameter whose effect can be off (beta) may be newer: files of
      // the model without the effect are as before, those with it say its version.
      if (mp->off) EXPECT_TRUE(is_optional(*f)) << p;
      else EXPECT_LE(f->since, m.schema_version) << p << " is newer than " << m.name << "'s files";
    }
  }
  EXPECT_FALSE(find_collision_model("sticky"));
}

}  // namespace
}  // namespace coolgas
