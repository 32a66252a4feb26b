// The default fit window's rule (analyze/curves/scaling_window.h) on
// synthetic E(t) whose answer follows from the rule by hand: samples at
// t = 10^(k/20), the quarter-decade secant from t_i to the first t_j >= 1.778 t_i.
#include "analyze/curves/scaling_window.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "common/error.h"

namespace coolgas {
namespace {

Table energy_table(const std::function<double(double)>& E, std::optional<double> L) {
  Table t;
  t.source = "synthetic";
  t.columns = {"t", "E"};
  if (L) t.provenance.emplace_back("L", std::to_string(*L));
  t.rows.push_back({0, E(0)});
  for (int k = -40; k <= 100; ++k) t.rows.push_back({std::pow(10.0, k / 20.0), E(std::pow(10.0, k / 20.0))});
  t.row_block.assign(t.rows.size(), 0);
  return t;
}

// Flat, then t^-1.2 from t = 10: the secant from t = 10^(19/20) to 10^(24/20)
// is 1.2 ln(1.585)/ln(1.778) = 0.96 < 1, from t = 10 it is 1.2: the start is 10.
// The end is 0.1 L^(5/2) = 178.9 for L = 20.
TEST(ScalingWindow, StartsWhereTheDecayReachesTMinusOneAndEndsAtTheFiniteSizeCrossover) {
  const auto E = [](double t) { return t < 10 ? 1.0 : std::pow(t / 10, -1.2); };
  const ChosenWindow c = scaling_window(energy_table(E, 20.0), FitColumns{});
  EXPECT_DOUBLE_EQ(*c.window.lo, 10);
  EXPECT_NEAR(*c.window.hi, 0.1 * std::pow(20.0, 2.5), 1e-9);
  EXPECT_FALSE(scaling_window(energy_table(E, std::nullopt), FitColumns{}).window.hi.has_value());
}

// A 2D run's table (its '# dimension: 2' line): the mean-field z = d/theta
// = (d+2)/2 = 2, so the end is 0.1 L^2 = 40 for L = 20, and the rule says so.
TEST(ScalingWindow, InTwoDimensionsEndsAtTheTwoDimensionalCrossover) {
  const auto E = [](double t) { return t < 10 ? 1.0 : std::pow(t / 10, -1.0); };
  Table t = energy_table(E, 20.0);
  t.provenance.emplace_back("dimension", "2");
  const ChosenWindow c = scaling_window(t, FitColumns{});
  EXPECT_DOUBLE_EQ(*c.window.lo, 10);
  EXPECT_NEAR(*c.window.hi, 40, 1e-9);
  EXPECT_NE(c.rule.find("0.1 L^2,"), std::string::npos) << c.rule;
  EXPECT_EQ(crossover_z(3), 2.5);
  t.provenance.back().second = "4";
  EXPECT_THROW(scaling_window(t, FitColumns{}), InputError);  // no dimension coolgas writes
}

// A 1D run's table ('# dimension: 1'): the same formula, z = (1+2)/2 = 3/2,
// so the end is 0.1 L^(3/2) = 12.65 for L = 40 (x = t/L^z of Ben-Naim et
// al.'s 1D cooling gas), and the rule names it.
TEST(ScalingWindow, InOneDimensionEndsAtTheOneDimensionalCrossover) {
  const auto E = [](double t) { return t < 1 ? 1.0 : std::pow(t, -1.0); };
  Table t = energy_table(E, 40.0);
  t.provenance.emplace_back("dimension", "1");
  const ChosenWindow c = scaling_window(t, FitColumns{});
  EXPECT_DOUBLE_EQ(*c.window.lo, 1);
  EXPECT_NEAR(*c.window.hi, 0.1 * std::pow(40.0, 1.5), 1e-12);
  EXPECT_EQ(crossover_z(1), 1.5);
  EXPECT_NE(c.rule.find("0.1 L^(3/2),"), std::string::npos) << c.rule;
}

// Flat, Haff's t^-2 from 10 to 100, then t^-1.2: the secant from 10^(39/20) = 89.1
// is (2 ln(100/89.1) + 1.2 ln(158.5/100))/ln(1.778) = 1.36 <= 3/2, from 10^(38/20)
// it is 1.52: the start is 10^(39/20), past Haff's law.
TEST(ScalingWindow, AfterHaffsRegimeStartsWhereTheDecayIsNoSteeperThanBurgers) {
  const auto E = [](double t) {
    if (t < 10) return 1.0;
    if (t < 100) return std::pow(t / 10, -2.0);
    return 0.01 * std::pow(t / 100, -1.2);
  };
  const ChosenWindow c = scaling_window(energy_table(E, std::nullopt), FitColumns{});
  EXPECT_DOUBLE_EQ(*c.window.lo, std::pow(10.0, 39 / 20.0));
}

// Still in Haff's law at the end of the data: no window, an InputError naming --t-window.
TEST(ScalingWindow, RefusesWhenHaffsLawIsNeverLeft) {
  const auto E = [](double t) { return 1 / ((1 + t) * (1 + t)); };
  try {
    scaling_window(energy_table(E, std::nullopt), FitColumns{});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--t-window"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace coolgas
