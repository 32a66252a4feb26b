// Mixtures ([[species]]) of the models beyond elastic and inelastic, as a
// user runs them: a viscoelastic mixture (each pair's own b) validates with
// its species; a ballistic aggregation that starts from a mixture starts
// each particle as an aggregate of its species' mass and diameter, keeps the
// total mass, writes no species (a merged aggregate has none), validates,
// resumes bit for bit after a kill (from its checkpoint) and from its last
// dump, and the tools read it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "common/hdf5_file.h"
#include "tests/support/killed_run.h"
#include "tests/support/one_run_suite.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::run_command;
using test::simulate;

// 600 unit spheres and 400 of diameter 1.5 and mass 3.375 (1.5^3), with the model's lines.
std::string mixture_scene(const std::string& collision, double t_end) {
  return "[system]\nN = 1000\nphi = 0.15\nseed = 11\nequilibrate = 1\n[collision]\n" + collision +
         "[run]\nt_end = " + std::to_string(t_end) + "\n[output]\ndumps_per_decade = 10\n\n[[species]]\n"
         "fraction = 0.6\ndiameter = 1\n\n[[species]]\nfraction = 0.4\ndiameter = 1.5\n";
}

// The same mixture aggregating, to t = 10.
constexpr const char* kAggregationMixtureScene = R"([system]
N = 1000
phi = 0.15
seed = 11
equilibrate = 1
[collision]
model = "aggregation"
[run]
t_end = 10
[output]
dumps_per_decade = 10

[[species]]
fraction = 0.6
diameter = 1

[[species]]
fraction = 0.4
diameter = 1.5
)";

TEST(MixtureModels, AViscoelasticMixtureValidatesWithItsSpecies) {
  const std::string dir = test::scratch_dir("mixture_viscoelastic");
  const std::string out = dir + "/visco.h5";
  const std::string scene =
      test::write_file(dir, "visco.toml", mixture_scene("model = \"viscoelastic\"\nviscoelastic_b = 0.3\n", 20));
  const auto r = run_command(simulate(scene + " -o " + out));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto v = run_command(test::bin("coolgas-validate") + " " + out);
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  h5::Handle f = h5::open_file(out, h5::Mode::kReadOnly);
  EXPECT_TRUE(h5::exists(f.id(), "particles/all/species"));
  const auto E = h5::read_all<double>(h5::open_dataset(f.id(), "observables/kinetic_energy/value").id());
  EXPECT_LT(E.back(), 0.9 * E.front());  // it cools
}

class AggregationMixture : public test::OneRunSuite<AggregationMixture> {
 public:
  static constexpr const char* kFolder = "mixture_aggregation";
  static constexpr const char* kScene = kAggregationMixtureScene;
};

TEST_F(AggregationMixture, StartsFromTheSpeciesKeepsTheMassAndWritesNoSpecies) {
  const auto v = run_command(test::bin("coolgas-validate") + " " + whole());
  EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
  h5::Handle f = h5::open_file(whole(), h5::Mode::kReadOnly);
  EXPECT_FALSE(h5::exists(f.id(), "particles/all/species"));
  EXPECT_FALSE(h5::exists(f.id(), "observables/species_kinetic_energy"));
  EXPECT_EQ(h5::read_attr_doubles(h5::open_group(f.id(), "parameters").id(), "species_mass", 16),
            (std::vector<double>{1.0, 3.375}));
  const h5::Handle mass = h5::open_dataset(f.id(), "particles/all/mass/value");
  const h5::Handle diameter = h5::open_dataset(f.id(), "particles/all/diameter/value");
  // Ids follow the tables: 600 of species 0, then 400 of species 1.
  const auto m0 = h5::read_row<double>(mass.id(), 0), d0 = h5::read_row<double>(diameter.id(), 0);
  ASSERT_EQ(m0.size(), 1000u);
  EXPECT_EQ(m0[599], 1.0);
  EXPECT_EQ(m0[600], 3.375);
  EXPECT_EQ(d0[599], 1.0);
  EXPECT_EQ(d0[600], 1.5);
  const hsize_t last = h5::read_all<double>(h5::open_dataset(f.id(), "restart/time").id()).size() - 1;
  const auto m = h5::read_row<double>(mass.id(), last), d = h5::read_row<double>(diameter.id(), last);
  EXPECT_NEAR(std::accumulate(m.begin(), m.end(), 0.0), 600 + 400 * 3.375, 1e-9);
  // Volumes add: the sum of d^3 is the start's.
  double volume = 0;
  for (const double x : d) volume += x * x * x;
  EXPECT_NEAR(volume, 600 + 400 * 3.375, 1e-9);
  EXPECT_LT(std::count_if(m.begin(), m.end(), [](double x) { return x > 0; }), 900);  // they merged
}

TEST_F(AggregationMixture, KilledItResumesBitForBitFromItsCheckpoint) {
  const std::string out = dir_ + "/killed.h5";
  test::expect_killed_run_resumes_bit_for_bit(simulate(scene_ + " -o " + out), out, whole());
}

TEST_F(AggregationMixture, ResumesFromItsLastDumpWithoutACheckpoint) {
  const std::string out = dir_ + "/dump.h5";
  test::expect_killed_run_resumes_from_its_last_dump(simulate(scene_ + " -o " + out), out, whole());
}

// The tools read it as they read equal spheres' aggregates: energies (no
// species columns) and the clusters' masses.
TEST_F(AggregationMixture, TheToolsReadIt) {
  const auto e = run_command(test::bin("coolgas-energy") + " " + whole());
  ASSERT_EQ(e.exit_code, 0) << e.err;
  EXPECT_EQ(e.out.find("T_species"), std::string::npos);
  const auto c = run_command(test::bin("coolgas-clusters") + " --series " + whole());
  EXPECT_EQ(c.exit_code, 0) << c.err;
}

}  // namespace
}  // namespace coolgas
