// The validator (data-schema/validator.h) and coolgas-validate: a file from
// H5mdWriter is valid; each deliberate corruption of it is reported as
// exactly the expected lines, by the library and by the program (exit 2).
#include "data-schema/validator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "common/error.h"
#include "common/trajectory/h5md_writer.h"
#include "common/trajectory/resume_frame.h"
#include "common/hdf5_file.h"
#include "tests/support/run_command.h"

namespace coolgas::schema {
namespace {

constexpr int kFrames = 3;

// N = 2 particles in a box of side 5, three dumps at t = 0, 1, 2 with one
// observable row each.
void write_good_file(const std::string& path) {
  RunParameters p;
  p.scene_toml = "[system]\nN = 2\n";
  p.seed = 11;
  p.N = 2;
  p.L = 5;
  p.phi = 2 * 3.141592653589793 / 6 / 125;
  p.T0 = 0.5;
  p.model = "inelastic";
  p.collision["r0"] = 0.5;
  p.collision["delta"] = 1e-4;
  H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
  for (int f = 0; f < kFrames; ++f) {
    const double pos[6] = {0.5, 1.5, 2.5, 3.0 + 0.5 * f, 4.0, 0.0};
    const std::int32_t img[6] = {0, 0, 0, f, -1, 2};
    const double vel[6] = {0.1 * f, 0.2, -0.3, -0.1 * f, -0.2, 0.3};
    w.add_observables({double(f), 10 * f, f, 0.5, {0, 0, 0}});
    w.add_frame({double(f), 10 * f, f, pos, img, vel});
  }
}

std::string fresh_file(const std::string& name) {
  std::string path = test::scratch_dir("schema_" + name) + "/run.h5";
  write_good_file(path);
  return path;
}

// Overwrites one number of a dataset (converted to the dataset's own type).
void set_value(hid_t file, const std::string& path, std::vector<hsize_t> index, double v) {
  h5::Handle ds = h5::open_dataset(file, path);
  h5::Handle space(H5Dget_space(ds.id()));
  std::vector<hsize_t> one(index.size(), 1);
  H5Sselect_hyperslab(space.id(), H5S_SELECT_SET, index.data(), nullptr, one.data(), nullptr);
  h5::Handle mem(H5Screate_simple(1, one.data(), nullptr));
  ASSERT_GE(H5Dwrite(ds.id(), H5T_NATIVE_DOUBLE, mem.id(), space.id(), H5P_DEFAULT, &v), 0);
}

void shrink(hid_t file, const std::string& path, hsize_t rows) {
  h5::Handle ds = h5::open_dataset(file, path);
  h5::resize_rows(ds.id(), rows);
}

void unlink(hid_t file, const std::string& path) { ASSERT_GE(H5Ldelete(file, path.c_str(), H5P_DEFAULT), 0); }

void set_attr(hid_t file, const std::string& group, const std::function<void(hid_t)>& write) {
  h5::Handle g = h5::open_group(file, group);
  write(g.id());
}

std::vector<std::string> lines(const Report& r) {
  std::vector<std::string> out;
  for (const Problem& p : r.problems) out.push_back(p.path + ": " + p.what);
  return out;
}

TEST(Validator, FileFromTheWriterIsValid) {
  const std::string path = fresh_file("good");
  {  // objects the profile does not list are allowed: later versions add them
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    h5::Handle g = h5::create_group(f.id(), "observables/from_the_future");
    h5::create_series(g.id(), "value", h5::Type::kInt32, {7}, 1);
  }
  const Report r = validate(path);
  EXPECT_EQ(lines(r), std::vector<std::string>{});
  EXPECT_EQ(r.summary.particles, 2);
  EXPECT_EQ(r.summary.frames, 3u);
  EXPECT_EQ(r.summary.observable_rows, 3u);

  const auto cli = test::run_command(test::bin("coolgas-validate") + " " + path);
  EXPECT_EQ(cli.exit_code, 0) << cli.err;
  EXPECT_EQ(cli.out, path + ": valid (coolgas H5MD profile v1, 2 particles, 3 frames, 3 observable rows)\n");
  EXPECT_EQ(cli.err, "");
}

// A run of rough particles (schema version 5): beta and inertia, the spins
// of each dump, the rotational energy of each observable row.
TEST(Validator, RoughFileFromTheWriterIsValid) {
  const std::string path = test::scratch_dir("schema_rough") + "/run.h5";
  RunParameters p;
  p.scene_toml = "[system]\nN = 2\n";
  p.N = 2;
  p.L = 5;
  p.phi = 2 * 3.141592653589793 / 6 / 125;
  p.T0 = 0.5;
  p.model = "elastic";
  p.collision = {{"r0", 1.0}, {"delta", 0.0}, {"beta", 0.5}};
  p.inertia = 0.4;
  {
    H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
    const double pos[6] = {0.5, 1.5, 2.5, 3.0, 4.0, 0.0}, vel[6] = {0.1, 0.2, -0.3, -0.1, -0.2, 0.3};
    const double spin[6] = {1, 2, 3, -1, -2, -3};
    const std::int32_t img[6] = {};
    ObservableRow row{0, 0, 0, 0.5, {0, 0, 0}};
    row.rotational_energy = 0.2;
    w.add_observables(row);
    FrameView frame{0, 0, 0, pos, img, vel};
    frame.angular_velocity = spin;
    w.add_frame(frame);
  }
  EXPECT_EQ(lines(validate(path)), std::vector<std::string>{});
  EXPECT_EQ(read_resume_frame(path).angular_velocity, (std::vector<double>{1, 2, 3, -1, -2, -3}));
}

// A mixture (schema version 6): the species table, each particle's species
// in each dump, each species' energy in each observable row; its overlap
// check takes each particle's diameter from its species (the two spheres of
// diameter 0.5 here sit 0.6 apart, which unit spheres could not).
TEST(Validator, MixtureFileFromTheWriterIsValid) {
  const std::string path = test::scratch_dir("schema_mixture") + "/run.h5";
  RunParameters p;
  p.scene_toml = "[system]\nN = 2\n";
  p.N = 2;
  p.L = 5;
  p.phi = 2 * 3.141592653589793 / 6 / 125 / 8;
  p.T0 = 0.5;
  p.model = "elastic";
  p.species_fraction = {0.5, 0.5};
  p.species_diameter = {0.5, 2.0};
  p.species_mass = {0.125, 8.0};
  const double pos[6] = {0.5, 1.5, 2.5, 1.1, 1.5, 2.5}, vel[6] = {0.1, 0.2, -0.3, -0.1, -0.2, 0.3};
  {
    H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
    const std::int32_t img[6] = {}, species[2] = {0, 0};
    ObservableRow row{0, 0, 0, 0.5, {0, 0, 0}};
    row.species_energy[0] = 0.5;
    w.add_observables(row);
    FrameView frame{0, 0, 0, pos, img, vel};
    frame.species = species;
    w.add_frame(frame);
  }
  EXPECT_EQ(lines(validate(path)), std::vector<std::string>{});
  EXPECT_EQ(read_resume_frame(path).species, (std::vector<std::int32_t>{0, 0}));
  // Of species 1 (diameter 2), the same pair overlaps.
  const std::string big = test::scratch_dir("schema_mixture") + "/big.h5";
  {
    H5mdWriter w = H5mdWriter::create(big, p, true, Geometry(3));
    const std::int32_t img[6] = {}, species[2] = {1, 2};
    w.add_observables(ObservableRow{0, 0, 0, 0.5, {0, 0, 0}});
    FrameView frame{0, 0, 0, pos, img, vel};
    frame.species = species;
    w.add_frame(frame);
  }
  EXPECT_EQ(lines(validate(big)),
            std::vector<std::string>{"/particles/all/species/value: [0, 1] = 2 is not one of the 2 the species of "
                                     "/parameters/species_fraction"});
}

struct Corruption {
  std::string name;
  std::function<void(hid_t)> apply;
  std::vector<std::string> expected;  // "path: problem", in report order
};

void PrintTo(const Corruption& c, std::ostream* os) { *os << c.name; }

class CorruptedFile : public ::testing::TestWithParam<Corruption> {};

TEST_P(CorruptedFile, IsReportedExactlyByLibraryAndProgram) {
  const Corruption& c = GetParam();
  const std::string path = fresh_file(c.name);
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    c.apply(f.id());
  }
  EXPECT_EQ(lines(validate(path)), c.expected);
  // Tiny blocks split frames into many reads: same findings, same indices.
  EXPECT_EQ(lines(validate(path, h5md_profile(), {.block_values = 2})), c.expected);

  const auto cli = test::run_command(test::bin("coolgas-validate") + " " + path);
  EXPECT_EQ(cli.exit_code, kExitInput);
  std::string want;
  for (const auto& l : c.expected) want += path + ": " + l + "\n";
  EXPECT_EQ(cli.out, want);
}

const Corruption kCorruptions[] = {
    {"deleted_dataset",
     [](hid_t f) { unlink(f, "particles/all/velocity/time"); },
     {"/particles/all/velocity/time: missing dataset"}},
    {"missing_group",
     [](hid_t f) { unlink(f, "h5md/author"); },
     {"/h5md/author: missing group (who ran the simulation)"}},
    {"wrong_N",
     [](hid_t f) { set_attr(f, "parameters", [](hid_t g) { h5::write_attr(g, "N", std::int64_t{3}); }); },
     {"/particles/all/position/value: shape (3, 2, 3) but the profile requires (F, N, 3) with N = 3 from /parameters/N",
      "/particles/all/image/value: shape (3, 2, 3) but the profile requires (F, N, 3) with N = 3 from /parameters/N",
      "/particles/all/velocity/value: shape (3, 2, 3) but the profile requires (F, N, 3) with N = 3 from "
      "/parameters/N"}},
    {"position_outside_box",
     [](hid_t f) {
       set_value(f, "particles/all/position/value", {1, 0, 2}, 5.0);
       set_value(f, "particles/all/position/value", {2, 1, 0}, -0.25);
     },
     {"/particles/all/position/value: [1, 0, 2] = 5 is outside [0, L) with L = 5 from /parameters/L (and 1 more)"}},
    {"nan_velocity",
     [](hid_t f) {
       set_value(f, "particles/all/velocity/value", {2, 1, 1}, std::numeric_limits<double>::quiet_NaN());
     },
     {"/particles/all/velocity/value: [2, 1, 1] = nan is not finite"}},
    {"infinite_observable",
     [](hid_t f) {
       set_value(f, "observables/total_momentum/value", {1, 0}, std::numeric_limits<double>::infinity());
     },
     {"/observables/total_momentum/value: [1, 0] = inf is not finite"}},
    {"time_goes_back",
     [](hid_t f) { set_value(f, "observables/kinetic_energy/time", {2}, 0.5); },
     {"/observables/kinetic_energy/time: [2] = 0.5 is less than an earlier 1: rows must not go back in time"}},
    {"missing_parameter",
     [](hid_t f) { ASSERT_GE(H5Adelete_by_name(f, "parameters", "phi", H5P_DEFAULT), 0); },
     {"/parameters: missing attribute 'phi' (float64, volume fraction)"}},
    {"parameter_of_wrong_type",
     [](hid_t f) { set_attr(f, "parameters", [](hid_t g) { h5::write_attr(g, "seed", 11.0); }); },
     {"/parameters: attribute 'seed' has type float64 but the profile requires int64"}},
    // The driven gas's attributes (schema version 4): both or neither, a
    // finite power above 0, and only in a file of the version that added them.
    {"driving_power_not_positive",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "schema_version", std::int64_t{4});
         h5::write_attr(g, "driving_power", -1.0);
         h5::write_attr(g, "driving_period", 0.5);
       });
     },
     {"/parameters: attribute 'driving_power' is -1 but must be a finite number above 0"}},
    {"driving_power_alone",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "schema_version", std::int64_t{4});
         h5::write_attr(g, "driving_power", 0.1);
       });
     },
     {"/parameters: attribute 'driving_power' without 'driving_period': a driven run writes both"}},
    {"driving_in_an_older_version",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "driving_power", 0.1);
         h5::write_attr(g, "driving_period", 0.5);
       });
     },
     {"/parameters: the driven gas's attributes in a file of schema version 1; they came with version 4"}},
    // Rough particles' attributes (schema version 5) come with their spins
    // and rotational energy, both attributes together, in a file of that version.
    {"rough_attributes_without_spins",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "schema_version", std::int64_t{5});
         h5::write_attr(g, "beta", 0.5);
         h5::write_attr(g, "inertia", 0.4);
       });
     },
     {"/particles/all/angular_velocity: missing element (angular velocities (2D: about z))",
      "/observables/rotational_energy: missing element (rotational energy per particle)"}},
    {"beta_alone_in_an_older_version",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) { h5::write_attr(g, "beta", 2.0); });
     },
     {"/parameters: attribute 'beta' without 'inertia': a run of rough particles writes both",
      "/parameters: rough particles' attributes in a file of schema version 1; they came with version 5",
      "/parameters: attribute 'beta' is 2; rough particles have beta in (-1, 1]",
      "/particles/all/angular_velocity: missing element (angular velocities (2D: about z))",
      "/observables/rotational_energy: missing element (rotational energy per particle)"}},
    // A mixture's table (schema version 6) comes whole, with each
    // particle's species and each species' energy, in a file of that version.
    {"species_table_without_species",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "schema_version", std::int64_t{6});
         h5::write_attr(g, "species_fraction", std::vector<double>{0.5, 0.5});
         h5::write_attr(g, "species_diameter", std::vector<double>{1, 2});
         h5::write_attr(g, "species_mass", std::vector<double>{1, 8});
       });
     },
     {"/particles/all/species: missing element (species of each particle (mixtures))",
      "/observables/species_kinetic_energy: missing element (kinetic energy per particle of each species "
      "(mixtures))"}},
    {"species_table_torn_in_an_older_version",
     [](hid_t f) {
       set_attr(f, "parameters", [](hid_t g) {
         h5::write_attr(g, "species_fraction", std::vector<double>{0.5, 0.4});
         h5::write_attr(g, "species_diameter", std::vector<double>{1, 2});
       });
     },
     {"/parameters: a mixture's species_fraction, species_diameter and species_mass are written together, one "
      "value per species each",
      "/particles/all/species: missing element (species of each particle (mixtures))",
      "/observables/species_kinetic_energy: missing element (kinetic energy per particle of each species "
      "(mixtures))"}},
    {"old_schema_version",
     [](hid_t f) { set_attr(f, "parameters", [](hid_t g) { h5::write_attr(g, "schema_version", std::int64_t{0}); }); },
     {"/parameters: attribute 'schema_version' is 0 but must be at least 1"}},
    {"wrong_h5md_version",
     [](hid_t f) {
       set_attr(f, "h5md", [](hid_t g) { h5::write_attr(g, "version", std::vector<std::int32_t>{1, 0}); });
     },
     {"/h5md: attribute 'version' is [1, 0] but the profile requires [1, 1]"}},
    {"boundary_not_periodic",
     [](hid_t f) {
       set_attr(f, "particles/all/box", [](hid_t g) {
         h5::write_attr(g, "boundary", std::vector<std::string>{"periodic", "periodic", "none"});
       });
     },
     {"/particles/all/box: attribute 'boundary' is [periodic, periodic, none] but the profile requires "
      "[periodic, periodic, periodic]"}},
    {"edges_not_the_box",
     [](hid_t f) {
       set_value(f, "particles/all/box/edges/value", {1, 2, 2}, 4.0);
     },
     {"/particles/all/box/edges/value: [1, 2, 2] = 4 but the box is diag(L, L, L) with L = 5 from /parameters/L"}},
    {"step_of_wrong_type",
     [](hid_t f) {
       unlink(f, "observables/collisions/step");
       h5::Handle g = h5::open_group(f, "observables/collisions");
       h5::create_series(g.id(), "step", h5::Type::kInt32, {}, 8);
     },
     {"/observables/collisions/step: type int32 but the profile requires int64"}},
    {"element_rows_disagree",
     [](hid_t f) { shrink(f, "particles/all/image/value", 2); },
     {"/particles/all/image: step, time and value have 3, 3 and 2 rows; they must agree"}},
    {"element_with_fewer_frames",
     [](hid_t f) {
       for (const char* d : {"step", "time", "value"}) shrink(f, std::string("particles/all/velocity/") + d, 2);
     },
     {"/particles/all/velocity: 2 rows but F = 3 from /particles/all/position"}},
    {"restart_rows_missing",
     [](hid_t f) { shrink(f, "restart/collisions", 2); },
     {"/restart/collisions: 2 rows but F = 3 from /particles/all/position"}},
    {"restart_time_differs",
     [](hid_t f) { set_value(f, "restart/time", {1}, 1.5); },
     {"/restart/time: [1] = 1.5 but /particles/all/position/time[1] = 1"}},
};

INSTANTIATE_TEST_SUITE_P(Validator, CorruptedFile, ::testing::ValuesIn(kCorruptions),
                         [](const auto& info) { return info.param.name; });

TEST(Validator, FileThatIsNotHdf5IsOneErrorLine) {
  const std::string dir = test::scratch_dir("schema_not_hdf5");
  const std::string text = dir + "/notes.h5";
  std::ofstream(text) << "not a trajectory\n";
  EXPECT_THROW(validate(text), InputError);
  for (const std::string& path : {text, dir + "/missing.h5"}) {
    const auto cli = test::run_command(test::bin("coolgas-validate") + " " + path);
    EXPECT_EQ(cli.exit_code, kExitInput);
    EXPECT_EQ(cli.out, "");
    EXPECT_EQ(test::line_count(cli.err), 1) << cli.err;
    // The message names the file; a long path is shortened in the middle to
    // keep the line within common/tool_main's limit, so look for its name.
    const std::string name = std::filesystem::path(path).filename().string();
    EXPECT_NE(cli.err.find(name), std::string::npos) << cli.err;
  }
}

// A later schema version adds a row to the table and nothing else: a file of
// that version must have it, files of earlier versions need not.
TEST(Validator, ElementAddedInALaterVersionIsRequiredOnlyFromThatVersion) {
  Profile v2 = h5md_profile();
  v2.version = 2;
  v2.elements.push_back({.path = "/particles/all/id",
                         .type = DataType::kInt64,
                         .row = {kParticles},
                         .rows = RowCount::kFrames,
                         .rule = ValueRule::kAny,
                         .meaning = "particle ids",
                         .presence = Presence::kRequired,
                         .since = 2,
                         .only_in = std::nullopt,
                         .fill = std::nullopt});
  const std::string path = fresh_file("later_version");
  EXPECT_EQ(lines(validate(path, v2)), std::vector<std::string>{});

  {
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    set_attr(f.id(), "parameters", [](hid_t g) { h5::write_attr(g, "schema_version", std::int64_t{2}); });
  }
  EXPECT_EQ(lines(validate(path, v2)), std::vector<std::string>{"/particles/all/id: missing element (particle ids)"});
}

}  // namespace
}  // namespace coolgas::schema
