// coolgas-energy's ensemble (analyze/energy/ensemble.h, analyze/energy/grid.h): the grid is
// the simulator's 10^(k/n), log-log interpolation is exact for power laws,
// and the mean and standard error over seeds are the textbook estimators.
#include "analyze/energy/ensemble.h"

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "analyze/energy/grid.h"
#include "analyze/energy/table.h"
#include "common/error.h"
#include "common/tsv.h"
#include "tests/support/run_command.h"
#include "tests/support/energy_test_runs.h"

namespace coolgas {
namespace {

TEST(EnergyGrid, PointsAreExactPowersOfTenToTheKOverN) {
  const auto g = log_time_grid(1, 100, 20);
  ASSERT_EQ(g.size(), 41u);
  for (int k = 0; k <= 40; ++k) EXPECT_DOUBLE_EQ(g[k], std::pow(10.0, k / 20.0));
}

TEST(EnergyGrid, EndsOffTheGridAreKept) {
  const auto g = log_time_grid(1.5, 95, 10);
  EXPECT_EQ(g.front(), 1.5);
  EXPECT_EQ(g.back(), 95.0);
  EXPECT_DOUBLE_EQ(g[1], std::pow(10.0, 0.2));  // the first grid point above 1.5
}

TEST(EnergyGrid, LogLogInterpolationIsExactForAPowerLaw) {
  const std::vector<double> t{1, 3, 20, 700};
  std::vector<double> y;
  for (double x : t) y.push_back(2.5 * std::pow(x, -1.2));
  for (double q : {1.0, 2.0, 10.0, 123.4, 700.0}) EXPECT_NEAR(interpolate_loglog(t, y, q) / (2.5 * std::pow(q, -1.2)), 1, 1e-13);
}

// Three seeds with E_k(t) = c_k t^-1.2 (t > 0), E_k(0) = e0_k, sampled at
// different times: the mean is mean(c) t^-1.2 on the grid, the error is the
// sample deviation of c over sqrt(3) times t^-1.2.
class EnsembleOfThree : public ::testing::Test {
 protected:
  void SetUp() override {
    const std::string dir = test::scratch_dir("energy_ensemble");
    const std::vector<std::vector<double>> times{{0, 0.5, 1, 7, 100, 1000}, {0, 0.2, 3, 50, 2000}, {0, 1, 10, 100, 800}};
    for (int k = 0; k < 3; ++k) {
      const std::string path = dir + "/s" + std::to_string(k) + ".h5";
      test::write_energy_run(path, test::paper_parameters(32, k), times[k],
                             [&](double t) { return t > 0 ? c[k] * std::pow(t, -1.2) : e0[k]; }, Geometry(3));
      runs.push_back(load_energy_run(path));
    }
  }
  const double c[3] = {1.0, 1.3, 0.85}, e0[3] = {2.0, 2.5, 1.6};
  std::vector<EnergyRun> runs;
};

TEST_F(EnsembleOfThree, MeanAndStandardErrorOnTheOverlap) {
  const auto rows = ensemble_energy(runs, 10);
  ASSERT_EQ(rows.front().t, 0);  // every run has t = 0: that row first
  EXPECT_NEAR(rows.front().E, (2.0 + 2.5 + 1.6) / 3, 1e-14);
  EXPECT_EQ(rows[1].t, 1.0);    // overlap starts at the latest first positive time (1) ...
  EXPECT_EQ(rows.back().t, 800.0);  // ... and ends at the earliest last time (800)
  const double mean_c = (1.0 + 1.3 + 0.85) / 3;
  double ss = 0;
  for (double ck : c) ss += (ck - mean_c) * (ck - mean_c);
  const double se_c = std::sqrt(ss / 2 / 3);
  const double mean_ratio = (1.0 / 2.0 + 1.3 / 2.5 + 0.85 / 1.6) / 3;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const double p = std::pow(rows[i].t, -1.2);
    EXPECT_NEAR(rows[i].E / (mean_c * p), 1, 1e-12) << rows[i].t;
    EXPECT_NEAR(rows[i].E_err / (se_c * p), 1, 1e-9) << rows[i].t;
    EXPECT_NEAR(rows[i].E_over_E0 / (mean_ratio * p), 1, 1e-12) << rows[i].t;
    EXPECT_EQ(rows[i].runs, 3);
  }
}

TEST_F(EnsembleOfThree, OneRunHasZeroErrorAndIsCopiedAtItsOwnTimes) {
  const auto rows = ensemble_energy({runs[2]}, 1);  // run 2 is sampled at 10^k
  ASSERT_EQ(rows.size(), 5u);                       // 0, 1, 10, 100, 800
  EXPECT_EQ(rows[2].t, 10.0);
  EXPECT_EQ(rows[2].E, 0.85 * std::pow(10.0, -1.2));  // no interpolation at a sample
  EXPECT_EQ(rows[2].E_err, 0.0);
}

TEST_F(EnsembleOfThree, DifferentPhysicsIsRefusedNamingTheParameter) {
  const std::string path = test::scratch_dir("energy_ensemble_L48") + "/L48.h5";
  test::write_energy_run(path, test::paper_parameters(48, 9), {0, 1, 10}, [](double) { return 1.0; }, Geometry(3));
  runs.push_back(load_energy_run(path));
  try {
    require_same_physics(runs);
    FAIL() << "runs with L = 32 and 48 were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("L = 32 vs 48"), std::string::npos) << e.what();
  }
}

// The bug of the hand-written parameter lists: b was neither compared nor shown.
TEST(EnergyEnsemble, ViscoelasticRunsWithDifferentBAreRefusedNamingB) {
  const std::string dir = test::scratch_dir("energy_viscoelastic_b");
  std::vector<EnergyRun> runs;
  for (double b : {0.1, 0.9}) {
    RunParameters p = test::paper_parameters(32, 1);
    p.model = "viscoelastic";
    p.collision.erase("r0");
    p.collision["viscoelastic_b"] = b;
    const std::string path = dir + "/b" + format_number(b) + ".h5";
    test::write_energy_run(path, p, {0, 1, 10}, [](double t) { return 1 / (1 + t); }, Geometry(3));
    runs.push_back(load_energy_run(path));
  }
  try {
    require_same_physics(runs);
    FAIL() << "runs with b = 0.1 and 0.9 were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("viscoelastic_b = 0.1 vs 0.9"), std::string::npos) << e.what();
  }
  std::ostringstream table;
  write_energy_table({{runs[0].info.path}, 20}, table);
  EXPECT_NE(table.str().find("# viscoelastic_b: 0.1\n"), std::string::npos) << table.str();
  EXPECT_EQ(table.str().find("# r0:"), std::string::npos) << table.str();
}

// A 1D run (rods on a ring) averages like any other; its table says
// '# dimension: 1', and a 1D run beside a 2D one of the same parameters is
// refused naming the dimensions.
TEST(EnergyEnsemble, OneDimensionalRunsSayTheirDimensionAndAreNotMixed) {
  const std::string dir = test::scratch_dir("energy_1d");
  const auto E = [](double t) { return 0.005 / (1 + t); };  // (d/2) T0 at t = 0 for d = 1, T0 = 0.01
  test::write_energy_run(dir + "/rods.h5", test::paper_parameters(32, 1), {0, 1, 10}, E, Geometry(1));
  test::write_energy_run(dir + "/disks.h5", test::paper_parameters(32, 2), {0, 1, 10}, E, Geometry(2));
  std::ostringstream table;
  write_energy_table({{dir + "/rods.h5"}, 20}, table);
  EXPECT_NE(table.str().find("# dimension: 1\n"), std::string::npos) << table.str();
  const std::vector<EnergyRun> runs{load_energy_run(dir + "/rods.h5"), load_energy_run(dir + "/disks.h5")};
  EXPECT_EQ(runs[0].info.dimension, 1);
  try {
    require_same_physics(runs);
    FAIL() << "a 1D and a 2D run were averaged";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("dimension = 1 vs 2"), std::string::npos) << e.what();
  }
}

TEST(EnergyEnsemble, NonPositiveEnergyIsRefused) {
  const std::string path = test::scratch_dir("energy_zero") + "/run.h5";
  test::write_energy_run(path, test::paper_parameters(32, 1), {0, 1, 2}, [](double t) { return t < 2 ? 1.0 : 0.0; }, Geometry(3));
  EXPECT_THROW(load_energy_run(path), InputError);
}

}  // namespace
}  // namespace coolgas
