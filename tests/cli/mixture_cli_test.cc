// Mixtures ([[species]]) as a user runs them: bad tables refused in one line
// before any file is written; a mixture's run validates (schema version 6,
// each particle's species in the dumps, each species' energy among the
// observables, the species table in /parameters) and resumes bit for bit
// after a kill, from its checkpoint, and from its last dump without one;
// coolgas-energy gives each species' temperature, coolgas-velocity
// --species one species' statistics and coolgas-clusters --species one
// species' clusters; a run of equal particles has none of the mixture's
// elements.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "common/hdf5_file.h"
#include "common/tsv.h"
#include "tests/support/killed_run.h"
#include "tests/support/one_run_suite.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::run_command;
using test::simulate;

// A small inelastic binary mixture: 600 unit spheres and 400 of diameter 1.5
// (mass 1.5^3), a fraction of a second.
constexpr const char* kMixtureScene = R"([system]
N = 1000
phi = 0.15
seed = 7
equilibrate = 1
[collision]
model = "inelastic"
r0 = 0.8
[run]
t_end = 50
[output]
dumps_per_decade = 10

[[species]]
fraction = 0.6
diameter = 1

[[species]]
fraction = 0.4
diameter = 1.5
)";

TEST(MixtureCli, BadTablesAreRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("mixture_bad_input");
  const std::string out = dir + "/out.h5";
  const auto refused = [&](const std::string& tables, const std::string& line) {
    const std::string scene =
        test::write_file(dir, "bad.toml", "[system]\nN = 1000\nphi = 0.15\n[run]\nt_end = 1\n" + tables);
    test::expect_simulate_refused(scene + " -o " + out, line, out);
  };
  refused("[[species]]\nfraction = 0.5\ndiameter = 1\n", "the [[species]] fractions add up to 0.5, not 1");
  refused("[[species]]\nfraction = 1\ndiameter = 0\n", "[[species]] 1 diameter = 0 is out of range");
  refused("[[species]]\nfraction = 1\ndiameter = 1\ncolour = 2\n", "unknown key 'colour' in [[species]] 1");
  test::expect_simulate_refused(test::write_file(dir, "mix.toml", kMixtureScene) + " -o " + out +
                                    " --set collision.beta=0.5",
                                "a rough mixture is not offered", out);
}

class MixtureRun : public test::OneRunSuite<MixtureRun> {
 public:
  static constexpr const char* kFolder = "mixture_run";
  static constexpr const char* kScene = kMixtureScene;
};

TEST_F(MixtureRun, ValidatesAsSchemaVersion6WithItsSpecies) {
  const auto v = run_command(test::bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  EXPECT_NE(v.out.find("profile v6"), std::string::npos) << v.out;
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  const h5::Handle p = h5::open_group(f.id(), "parameters");
  EXPECT_EQ(h5::read_attr_doubles(p.id(), "species_fraction", 16), (std::vector<double>{0.6, 0.4}));
  EXPECT_EQ(h5::read_attr_doubles(p.id(), "species_diameter", 16), (std::vector<double>{1.0, 1.5}));
  EXPECT_EQ(h5::read_attr_doubles(p.id(), "species_mass", 16), (std::vector<double>{1.0, 3.375}));
  // Ids follow the tables: 600 of species 0, then 400 of species 1.
  const auto species = h5::read_row<std::int32_t>(h5::open_dataset(f.id(), "particles/all/species/value").id(), 0);
  ASSERT_EQ(species.size(), 1000u);
  EXPECT_EQ(species[599], 0);
  EXPECT_EQ(species[600], 1);
  // At t = 0 each species is Maxwellian at T0 (the whole rescaled to T0
  // exactly): E_k = (3/2) T0 within a few of its 1/sqrt(N_k) noise.
  const double T0 = h5::read_attr_double(p.id(), "T0");
  const auto E = h5::read_row<double>(h5::open_dataset(f.id(), "observables/species_kinetic_energy/value").id(), 0);
  ASSERT_EQ(E.size(), 2u);
  EXPECT_NEAR(E[0] / (1.5 * T0), 1.0, 4 * std::sqrt(2.0 / (3 * 600)));
  EXPECT_NEAR(E[1] / (1.5 * T0), 1.0, 4 * std::sqrt(2.0 / (3 * 400)));
  const auto e = h5::read_row<double>(h5::open_dataset(f.id(), "observables/kinetic_energy/value").id(), 0);
  EXPECT_NEAR(e.at(0), (600 * E[0] + 400 * E[1]) / 1000, 1e-12 * e.at(0));
}

TEST_F(MixtureRun, KilledItResumesBitForBitFromItsCheckpoint) {
  const std::string out = dir_ + "/killed.h5";
  test::expect_killed_run_resumes_bit_for_bit(simulate(scene_ + " -o " + out), out, whole());
}

// Without the checkpoint a resume starts from the last dump: its species
// are read back with the positions (the run goes on, valid, to the end).
TEST_F(MixtureRun, ResumesFromItsLastDumpWithoutACheckpoint) {
  const std::string out = dir_ + "/dump.h5";
  test::expect_killed_run_resumes_from_its_last_dump(simulate(scene_ + " -o " + out), out, whole());
}

// coolgas-energy adds each species' temperature per axis; at t = 0 each is
// T0 within a few of its 1/sqrt(N_k) noise, and the columns are the
// observables' 2 E_k/3 exactly.
TEST_F(MixtureRun, TheEnergyTableHasEachSpeciesTemperature) {
  const auto r = run_command(test::bin("coolgas-energy") + " " + whole());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  const Table t = read_table(in, "energy");
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  const double T0 = h5::read_attr_double(h5::open_group(f.id(), "parameters").id(), "T0");
  const auto E = h5::read_row<double>(h5::open_dataset(f.id(), "observables/species_kinetic_energy/value").id(), 0);
  ASSERT_EQ(t.column_values("t").at(0), 0.0);
  EXPECT_EQ(t.column_values("T_species_0").at(0), E[0] / 1.5);
  EXPECT_EQ(t.column_values("T_species_1").at(0), E[1] / 1.5);
  EXPECT_NEAR(t.column_values("T_species_0").at(0) / T0, 1.0, 4 * std::sqrt(2.0 / (3 * 600)));
}

// coolgas-velocity --species K: one species' velocities alone; at t = 0 each
// is a Maxwellian of its own mass, so v_rms^2 m_k is about T0 for both (the
// mixture of the two is no Gaussian, its kappa far from 0).
TEST_F(MixtureRun, TheVelocityToolTakesOneSpecies) {
  const auto series = [&](const std::string& option) {
    // --tail-from 1 --min-count 3: a tail fit (its beta) even for 400 particles
    const auto r = run_command(test::bin("coolgas-velocity") + " --series --time 0 --tail-from 1 --min-count 3 " +
                               option + " " + whole());
    EXPECT_EQ(r.exit_code, 0) << r.err;
    std::istringstream in(r.out);
    return read_table(in, "velocity");
  };
  const Table a = series("--species 0"), b = series("--species 1"), both = series("");
  const double va = a.column_values("v_rms").at(0), vb = b.column_values("v_rms").at(0);
  EXPECT_NEAR(vb * vb * 3.375 / (va * va), 1.0, 0.15);
  EXPECT_LT(std::fabs(a.column_values("kappa").at(0)), 4 * a.column_values("kappa_err").at(0));
  EXPECT_GT(both.column_values("kappa").at(0), 4 * both.column_values("kappa_err").at(0));
  test::expect_refused_with_one_line(run_command(test::bin("coolgas-velocity") + " --species 2 " + whole()),
                                     "--species 2: ", "coolgas-velocity --species 2");
}

// coolgas-clusters --species K: one species' clusters, every particle of it
// counted (M1 V = N_k: 600 and 400). A species' occupied cells, or bonds,
// are some of the whole mixture's (its bonds between two particles of one
// species are the same), so each cluster of a species lies inside one of
// the whole's: together the species have at least as many clusters, none
// larger than the whole's largest.
TEST_F(MixtureRun, TheClustersToolTakesOneSpecies) {
  for (const std::string definition : {"cells", "contact"}) {
    const auto series = [&](const std::string& option) {
      const auto r = run_command(test::bin("coolgas-clusters") + " --series --definition " + definition + " " +
                                 option + " " + whole());
      EXPECT_EQ(r.exit_code, 0) << r.err;
      std::istringstream in(r.out);
      return read_table(in, "clusters");
    };
    const Table a = series("--species 0"), b = series("--species 1"), both = series("");
    EXPECT_EQ(a.get("species"), "0");
    const double V = std::pow(std::stod(a.get("L").value()), 3);
    ASSERT_EQ(a.rows.size(), both.rows.size());
    for (std::size_t i = 0; i < a.rows.size(); ++i) {
      SCOPED_TRACE(definition + ", dump " + std::to_string(i));
      const auto column = [&](const Table& t, const char* name) { return t.rows[i][t.column(name)]; };
      EXPECT_NEAR(column(a, "M1") * V, 600, 1e-9);
      EXPECT_NEAR(column(b, "M1") * V, 400, 1e-9);
      EXPECT_GE(column(a, "M0") + column(b, "M0"), column(both, "M0") * (1 - 1e-12));
      EXPECT_LE(column(a, "M_max"), column(both, "M_max"));
      EXPECT_LE(column(b, "M_max"), column(both, "M_max"));
    }
  }
  test::expect_refused_with_one_line(run_command(test::bin("coolgas-clusters") + " --species 2 " + whole()),
                                     "--species 2: ", "coolgas-clusters --species 2");
}

TEST_F(MixtureRun, EqualParticlesHaveNoSpecies) {
  const std::string out = dir_ + "/equal.h5";
  const std::string scene = test::write_file(dir_, "equal.toml",
                                             "[system]\nN = 1000\nphi = 0.15\nequilibrate = 1\n[run]\nt_end = 1\n");
  ASSERT_EQ(run_command(simulate(scene + " -o " + out)).exit_code, 0);
  h5::Handle f = h5::open_file(out, h5::Mode::kReadOnly);
  EXPECT_FALSE(h5::exists(f.id(), "particles/all/species"));
  EXPECT_FALSE(h5::exists(f.id(), "observables/species_kinetic_energy"));
  EXPECT_FALSE(h5::has_attr(h5::open_group(f.id(), "parameters").id(), "species_fraction"));
  for (const char* tool : {"coolgas-velocity", "coolgas-clusters"})
    test::expect_refused_with_one_line(run_command(test::bin(tool) + " --species 0 " + out), "no species",
                                       std::string(tool) + " --species 0 EQUAL");
}

}  // namespace
}  // namespace coolgas
