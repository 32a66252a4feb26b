// coolgas-clusters --species K on mixture files written by the real H5MD
// writer. An exact identity: species K of a mixture is labelled as a file
// holding only species K's particles is labelled (a one-species mixture of
// its diameter), every table, both definitions, d = 1, 2, 3. On a hand-made
// frame the masses are those counted by hand: the contacts' bonds scale with
// each pair's contact distance (sigma_i + sigma_j)/2, for the whole mixture
// as for one species. Bad --species values are refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>

#include "analyze/clusters/cluster_table.h"
#include "analyze/clusters/tool.h"
#include "common/error.h"
#include "common/random.h"
#include "common/trajectory/h5md_writer.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// A mixture's dumps: each particle's species, a species table of diameters
// (masses diameter^d), and the positions of each dump (3 numbers a particle).
struct Mixture {
  Geometry g{3};
  double L = 0;
  std::vector<double> diameter;       // per species
  std::vector<std::int32_t> species;  // per particle
  std::vector<std::vector<double>> dumps;
};

std::string write_mixture(const std::string& path, const Mixture& m) {
  const std::size_t n = m.species.size();
  RunParameters p;
  p.N = std::int64_t(n);
  p.L = m.L;
  p.seed = 5;
  p.model = "elastic";
  double covered = 0;
  for (std::size_t k = 0; k < m.diameter.size(); ++k) {
    const auto count = double(std::count(m.species.begin(), m.species.end(), std::int32_t(k)));
    p.species_fraction.push_back(count / double(n));
    p.species_diameter.push_back(m.diameter[k]);
    p.species_mass.push_back(m.g.mass_of_diameter(m.diameter[k]));
    covered += count * m.g.ball_measure(m.diameter[k] / 2);
  }
  p.phi = covered / m.g.box_measure(m.L);
  H5mdWriter w = H5mdWriter::create(path, p, true, m.g);
  const std::vector<std::int32_t> img(3 * n, 0);
  const std::vector<double> vel(3 * n, 0.0);
  for (std::size_t f = 0; f < m.dumps.size(); ++f) {
    FrameView view{double(f), std::int64_t(f), 0, m.dumps[f].data(), img.data(), vel.data()};
    view.species = m.species.data();
    w.add_frame(view);
  }
  return path;
}

// Species k's particles alone, as a one-species mixture of its diameter.
Mixture only_species(const Mixture& m, int k) {
  Mixture one{m.g, m.L, {m.diameter[std::size_t(k)]}, {}, {}};
  for (const auto& positions : m.dumps) {
    one.dumps.emplace_back();
    for (std::size_t i = 0; i < m.species.size(); ++i)
      if (m.species[i] == k) one.dumps.back().insert(one.dumps.back().end(), &positions[3 * i], &positions[3 * i + 3]);
  }
  one.species.assign(one.dumps.front().size() / 3, 0);
  return one;
}

Table run(const std::string& input, const std::string& definition, ClusterTable table,
          std::optional<int> species = {}) {
  ClustersOptions opt;
  opt.input = input;
  opt.definition = definition;
  opt.series = table == ClusterTable::kSeries;
  opt.scaled = table == ClusterTable::kScaled;
  opt.species = species;
  std::stringstream out;
  run_clusters(opt, out);
  return read_table(out, input);
}

// Ideal-gas points, 60 % of diameter 1 and 40 % of diameter 1.5, two dumps,
// dense enough for clusters of many sizes by either definition.
Mixture random_mixture(Geometry g) {
  Mixture m{g, g.d() == 3 ? 12.0 : (g.d() == 2 ? 40.0 : 300.0), {1.0, 1.5}, {}, {}};
  const std::size_t n = g.d() == 1 ? 300 : 600;
  Random rng(17 + std::uint64_t(g.d()));
  for (std::size_t i = 0; i < n; ++i) m.species.push_back(rng.uniform() < 0.6 ? 0 : 1);
  for (int f = 0; f < 2; ++f) {
    m.dumps.emplace_back(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (int c = 0; c < g.d(); ++c) m.dumps.back()[3 * i + std::size_t(c)] = m.L * rng.uniform();
  }
  return m;
}

class SpeciesInEveryDimension : public ::testing::TestWithParam<int> {};

TEST_P(SpeciesInEveryDimension, OneSpeciesIsLabelledAsAFileOfItsParticlesAlone) {
  const Mixture m = random_mixture(Geometry(GetParam()));
  const std::string dir = test::scratch_dir("clusters_species_" + std::to_string(GetParam()));
  const std::string mixture = write_mixture(dir + "/mixture.h5", m);
  for (int k = 0; k < 2; ++k) {
    const std::string alone = write_mixture(dir + "/alone" + std::to_string(k) + ".h5", only_species(m, k));
    for (const char* definition : {"cells", "contact", "contact:1.3"})
      for (ClusterTable table : {ClusterTable::kDistribution, ClusterTable::kScaled, ClusterTable::kSeries}) {
        SCOPED_TRACE(std::string(definition) + ", species " + std::to_string(k));
        const Table of_mixture = run(mixture, definition, table, k), of_alone = run(alone, definition, table);
        EXPECT_EQ(of_mixture.columns, of_alone.columns);
        EXPECT_EQ(of_mixture.rows, of_alone.rows);
        EXPECT_EQ(of_mixture.row_block, of_alone.row_block);
        EXPECT_EQ(of_mixture.get("species"), std::to_string(k));
        EXPECT_EQ(of_alone.get("species"), std::nullopt);
        // The one species of a file is all of it.
        EXPECT_EQ(run(alone, definition, table, 0).rows, of_alone.rows);
      }
    // Every particle of the species in some cluster: M1 = N_k / V.
    const Table series = run(mixture, "contact", ClusterTable::kSeries, k);
    const double N_k = double(std::count(m.species.begin(), m.species.end(), k));
    EXPECT_DOUBLE_EQ(series.rows.at(0)[series.column("M1")], N_k / m.g.box_measure(m.L));
    EXPECT_GT(series.rows.at(0)[series.column("M_max")], 3);  // clusters, not just singletons
  }
}

INSTANTIATE_TEST_SUITE_P(D, SpeciesInEveryDimension, ::testing::Values(1, 2, 3));

// A box of side 10 (10 unit cells a side), species 0 of diameter 1 and
// species 1 of diameter 2: a chain along x, 1 -- 1 (2.1 apart: bonded at
// 1.1 x 2 = 2.2), 1 -- 0 (1.6: bonded at 1.1 x 1.5 = 1.65), 0 -- 0 (1.05),
// and a 1 bonded to the first across the face x = 0 (2.05); a 1 alone, and
// two 0s 1.6 apart along y (in neighbouring cells, but not in contact). The
// unit bond 1.1 would join only the chain's two 0s, the largest pair's
// 2.2 the last two 0s as well.
Mixture hand_made() {
  Mixture m{Geometry(3), 10, {1, 2}, {1, 1, 0, 0, 1, 1, 0, 0}, {}};
  m.dumps.push_back({2, 2, 2, 4.1, 2, 2, 5.7, 2, 2, 6.75, 2, 2, 9.95, 2, 2, 2, 6, 6, 6, 6, 6, 6, 7.6, 6});
  return m;
}

// The series row's M0 V, M1 V and M_max.
std::vector<double> counts(const Table& t) {
  const double V = 1000;
  const auto& r = t.rows.at(0);
  return {std::round(r[t.column("M0")] * V), std::round(r[t.column("M1")] * V), r[t.column("M_max")]};
}

TEST(ClusterSpecies, ContactsScaleWithEachPairsDiameters) {
  const std::string path = write_mixture(test::scratch_dir("clusters_species_hand") + "/run.h5", hand_made());
  // Contacts: the chain of five, three alone; species 1: its three of the chain, one alone; species 0: its
  // two of the chain, two alone.
  EXPECT_EQ(counts(run(path, "contact", ClusterTable::kSeries)), (std::vector<double>{4, 8, 5}));
  EXPECT_EQ(counts(run(path, "contact", ClusterTable::kSeries, 1)), (std::vector<double>{2, 4, 3}));
  EXPECT_EQ(counts(run(path, "contact", ClusterTable::kSeries, 0)), (std::vector<double>{3, 4, 2}));
  // Unit cells (the chain's x cells 2, 4, 5, 6, 9): cells 4 to 6 joined, the last two 0s joined, the others
  // alone; species 1 all apart.
  EXPECT_EQ(counts(run(path, "cells", ClusterTable::kSeries)), (std::vector<double>{5, 8, 3}));
  EXPECT_EQ(counts(run(path, "cells", ClusterTable::kSeries, 1)), (std::vector<double>{4, 4, 1}));
  EXPECT_EQ(counts(run(path, "cells", ClusterTable::kSeries, 0)), (std::vector<double>{2, 4, 2}));
  const Table t = run(path, "contact", ClusterTable::kSeries, 1);
  EXPECT_DOUBLE_EQ(t.rows.at(0)[t.column("largest_fraction")], 3.0 / 4);
  EXPECT_NE(t.get("contact")->find("sigma_ij"), std::string::npos);
  // The longest bond is the cutoff times the largest diameter labelled: 2.6 x 2 > L/2 for species 1, not for 0.
  EXPECT_EQ(counts(run(path, "contact:2.6", ClusterTable::kSeries, 0)), (std::vector<double>{2, 4, 2}));
  try {
    run(path, "contact:2.6", ClusterTable::kSeries);
    ADD_FAILURE() << "a bond longer than L/2 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the largest diameter 2 = 5.2, exceeds half the box side, L/2 = 5"),
              std::string::npos)
        << e.what();
  }
}

std::string refusal(const std::string& path, int species) {
  try {
    run(path, "cells", ClusterTable::kSeries, species);
  } catch (const InputError& e) {
    return e.what();
  }
  return "accepted";
}

TEST(ClusterSpecies, ASpeciesTheFileDoesNotHaveIsRefused) {
  const std::string dir = test::scratch_dir("clusters_species_refused");
  const std::string path = write_mixture(dir + "/run.h5", hand_made());
  EXPECT_EQ(refusal(path, 2), "--species 2: " + path + " has 2 species, 0 to 1");
  EXPECT_EQ(refusal(path, -1), "--species -1: " + path + " has 2 species, 0 to 1");
  const std::string equal = dir + "/equal.h5";
  {
    RunParameters p;
    p.N = 1;
    p.L = 4;
    H5mdWriter w = H5mdWriter::create(equal, p, true, Geometry(3));
    const double x[3] = {1, 1, 1}, v[3] = {};
    const std::int32_t img[3] = {};
    w.add_frame({0.0, 0, 0, x, img, v});
  }
  EXPECT_EQ(refusal(equal, 0),
            equal + ": no species (its particles are all alike); --species needs a mixture's run ([[species]])");
}

}  // namespace
}  // namespace coolgas
