// pipelines/mmax-jump.sh on synthetic tables whose answers follow by hand:
// M_max(t) a power law t^1 with one steep stretch t^4 between t = 10^2 and
// 10^2.4, and E(t) flat to t = 1, then t^-2 (Haff's late-time law) to t = 300,
// then t^-6/5 (the paper's inhomogeneous cooling).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "common/tsv.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

constexpr double kN = 1e7;  // particles: M_max / N stays below 1 to t = 10^4

// ln M_max: slope 1, slope 4 on [10^2, 10^2.4], slope 1 again; M(1) = 10.
double mmax(double t) {
  const double x = std::log10(t);
  const double steep = std::min(std::max(x - 2.0, 0.0), 0.4);
  return 10.0 * std::pow(10.0, x + 3.0 * steep);
}
// E = 1 to t = 1, t^-2 to t = 300, then 300^-2 (t/300)^-1.2.
double energy(double t) {
  if (t <= 1) return 1.0;
  if (t <= 300) return 1.0 / (t * t);
  return std::pow(300.0, -2.0) * std::pow(t / 300.0, -1.2);
}

// M_max at t = 0 and 5 dumps a decade from 10^-2 to 10^x_end; E 20 a decade.
void write_tables(const std::string& dir, double x_end, double fraction_0) {
  std::ofstream m(dir + "/mmax.tsv");
  m << "t\tM_max\tlargest_fraction\n# format: coolgas-table 2\n# N: " << kN << "\n";
  m << "0\t" << fraction_0 * kN << "\t" << fraction_0 << "\n";
  for (int k = -10; k <= std::lround(5 * x_end); ++k) {
    const double t = std::pow(10.0, k / 5.0);
    m.precision(17);
    m << t << "\t" << mmax(t) << "\t" << mmax(t) / kN << "\n";
  }
  std::ofstream e(dir + "/energy.tsv");
  e << "t\tE\n# format: coolgas-table 2\n";
  e.precision(17);
  e << "0\t1\n";
  for (int k = -40; k <= std::lround(20 * x_end); ++k) {
    const double t = std::pow(10.0, k / 20.0);
    e << t << "\t" << energy(t) << "\n";
  }
}

Table jump_table(const std::string& dir) {
  const auto r = test::run_command("sh " + test::source("pipelines/mmax-jump.sh") + " " + dir + "/mmax.tsv " + dir +
                                   "/energy.tsv > " + dir + "/jump.tsv");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return read_table(dir + "/jump.tsv");
}
double at(const Table& t, const std::string& column) { return t.column_values(column).at(0); }

TEST(MmaxJump, FindsTheSteepStretchAndWhereTheDecayLeavesHaffsLaw) {
  const std::string dir = test::scratch_dir("mmax_jump");
  write_tables(dir, 4.0, 1e-7);
  const Table j = jump_table(dir);
  // The only 0.4-decade chord inside the steep stretch: slope 4, centre 10^2.2.
  EXPECT_NEAR(at(j, "slope_max"), 4.0, 1e-5);
  EXPECT_NEAR(at(j, "t_from"), 100.0, 1e-3);
  EXPECT_NEAR(at(j, "t_jump"), std::pow(10.0, 2.2), 1e-3);
  EXPECT_NEAR(at(j, "span"), 0.4, 1e-6);
  EXPECT_EQ(at(j, "jump"), 1.0);
  // Quarter-decade chords: slope 2 inside [1, 300]; the chord from 10^2.40 has
  // 0.31 of its length before t = 300, theta = 1.2 + 0.8 * 0.31 = 1.45 < 3/2
  // (the one from 10^2.35: 1.61), so t_inhom is its centre 10^2.525.
  EXPECT_NEAR(at(j, "theta_peak"), 2.0, 1e-6);
  EXPECT_NEAR(at(j, "t_inhom") / std::pow(10.0, 2.525), 1.0, 1e-5);
  EXPECT_EQ(at(j, "inhom"), 1.0);
  // M_max/N there, on the slope-1 stretch after the steep one.
  EXPECT_NEAR(at(j, "fraction_inhom") / (mmax(std::pow(10.0, 2.525)) / kN), 1.0, 1e-5);
}

TEST(MmaxJump, ARunEndingBeforeTheJumpHasNoneAndIsStillInHaffsRegime) {
  const std::string dir = test::scratch_dir("mmax_jump");
  write_tables(dir, 2.0, 1e-7);  // to t = 100
  const Table j = jump_table(dir);
  EXPECT_NEAR(at(j, "slope_max"), 1.0, 1e-6);  // the power law t^1 only
  EXPECT_EQ(at(j, "jump"), 0.0);
  EXPECT_EQ(at(j, "inhom"), 0.0);  // E(t) still falls as t^-2 at the end
  EXPECT_NEAR(at(j, "t_end"), 100.0, 1e-3);
}

TEST(MmaxJump, APercolatingStartHasNoJump) {
  const std::string dir = test::scratch_dir("mmax_jump");
  write_tables(dir, 4.0, 0.6);  // the largest cluster holds 0.6 of the particles at t = 0
  const Table j = jump_table(dir);
  EXPECT_NEAR(at(j, "slope_max"), 4.0, 1e-5);
  EXPECT_EQ(at(j, "jump"), 0.0);
}

}  // namespace
}  // namespace coolgas
