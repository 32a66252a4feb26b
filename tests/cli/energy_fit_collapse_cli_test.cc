// coolgas-energy, coolgas-fit and coolgas-collapse run as a user would:
// they chain through pipes, and every bad input (empty, wrong file type,
// missing datasets or columns, NaN) gives exactly one error line and exit code 2.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <fstream>

#include "common/hdf5_file.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/energy_test_runs.h"

namespace coolgas {
namespace {

using test::bin;
using test::expect_one_error_line;
using test::run_command;

// Two seeds of L = 16 and 32 whose energies follow Eq. (2) of the paper with
// theta = 1.2, z = 2.5: E = L^{-3} f(t / L^2.5), f(x) = x^-1.2 (1 + x)^-0.63.
class EnergyFitCollapseCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("energy_cli"));
    std::vector<double> times{0};
    for (int k = 0; k <= 120; ++k) times.push_back(std::pow(10.0, k / 20.0));
    for (double L : {16.0, 32.0})
      for (int seed : {1, 2}) {
        const double amp = 1 + 0.01 * seed;
        test::write_energy_run(path(L, seed), test::paper_parameters(L, seed), times, [=](double t) {
          const double x = std::max(t, 1.0) / std::pow(L, 2.5);
          return amp * std::pow(L, -3.0) * std::pow(x, -1.2) * std::pow(1 + x, -0.63);
        }, Geometry(3));
      }
  }
  static std::string path(double L, int seed) {
    return *dir + "/L" + std::to_string(int(L)) + "_s" + std::to_string(seed) + ".h5";
  }
  static std::string file(const std::string& name, const std::string& text) {
    std::string p = *dir + "/" + name;
    std::ofstream(p) << text;
    return p;
  }
  static inline std::string* dir = nullptr;
};

TEST_F(EnergyFitCollapseCli, EnergyFitAndCollapseChainThroughPipes) {
  const std::string e16 = *dir + "/e16.tsv", e32 = *dir + "/e32.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(16, 1) + " " + path(16, 2) + " > " + e16).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(32, 1) + " " + path(32, 2) + " > " + e32).exit_code, 0);
  // For t << L^z = 5793 the energy is t^-1.2: the local slope is 1.2 + 0.63 x/(1 + x) < 1.2011 for t <= 10.
  auto fit = run_command(bin("coolgas-energy") + " " + path(32, 1) + " " + path(32, 2) + " | " + bin("coolgas-fit") +
                         " --power --window 1:10 -");
  ASSERT_EQ(fit.exit_code, 0) << fit.err;
  const std::string last = fit.out.substr(fit.out.rfind('\n', fit.out.size() - 2) + 1);
  EXPECT_NEAR(std::stod(last), 1.2, 2e-3) << fit.out;
  auto collapse = run_command(bin("coolgas-collapse") + " --optimize --bootstrap 0 --summary --theta 1.1 --z 2.3 " +
                              e16 + " " + e32);
  ASSERT_EQ(collapse.exit_code, 0) << collapse.err;
  const std::string row = collapse.out.substr(collapse.out.rfind('\n', collapse.out.size() - 2) + 1);
  double theta = 0, theta_err = 0, z = 0;
  ASSERT_EQ(std::sscanf(row.c_str(), "%lf %lf %lf", &theta, &theta_err, &z), 3) << collapse.out;
  EXPECT_NEAR(theta, 1.2, 0.01);
  EXPECT_NEAR(z, 2.5, 0.02);
}

// With z theta held at 3 (the paper's E L^3 against t/L^(5/2)), the data's
// own product, z alone is found again from a start far off, theta = 3/z, in
// the same row as the free fit; the product needs --optimize.
TEST_F(EnergyFitCollapseCli, FixedProductCollapseFindsZAndHoldsTheProduct) {
  std::string tables;
  for (double L : {16.0, 32.0})
    for (int seed : {1, 2}) {
      const std::string e = *dir + "/run_L" + std::to_string(int(L)) + "_s" + std::to_string(seed) + ".tsv";
      ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(L, seed) + " > " + e).exit_code, 0);
      tables += " " + e;
    }
  auto r = run_command(bin("coolgas-collapse") + " --optimize --z-theta 3 --z 2 --summary" + tables);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.out.find("# z_theta: 3 (fixed"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("jackknife over whole runs"), std::string::npos) << r.out;
  const std::string row = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
  double theta = 0, theta_err = 0, z = 0, z_err = 0, quality = -1;
  ASSERT_EQ(std::sscanf(row.c_str(), "%lf %lf %lf %lf %lf", &theta, &theta_err, &z, &z_err, &quality), 5) << r.out;
  EXPECT_NEAR(z, 2.5, 0.01);
  EXPECT_NEAR(theta * z, 3.0, 1e-12);
  EXPECT_GE(quality, 0.0);
  expect_one_error_line(run_command(bin("coolgas-collapse") + " --z-theta 3" + tables), "--z-theta");
}

TEST_F(EnergyFitCollapseCli, AnEtaWindowBeyondTheDataGivesNanAndANoteNotARefusal) {
  const std::string e16 = *dir + "/e16.tsv", e32 = *dir + "/e32.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(16, 1) + " > " + e16).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(32, 1) + " > " + e32).exit_code, 0);
  // The runs end at t = 1e6: x = t/L^2.5 reaches 977 for L = 16, so no point lies in 1e4:1e5.
  auto r = run_command(bin("coolgas-collapse") + " --theta 1.2 --z 2.5 --summary --eta-window 1e4:1e5 " + e16 + " " + e32);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("--eta-window 10000:1e+05 holds 0 scaled points"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("eta is nan"), std::string::npos) << r.err;
  EXPECT_EQ(r.out.substr(0, r.out.find('\n')), "theta\ttheta_err\tz\tz_err\tquality\teta\teta_err");
  EXPECT_NE(r.out.find("# eta: nan\n"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("# eta_note: fewer than 3 scaled points in the window\n"), std::string::npos) << r.out;
  const std::string row = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
  EXPECT_EQ(row.substr(0, 4), "1.2\t") << row;
  EXPECT_EQ(row.substr(row.size() - 8), "nan\tnan\n") << row;
}

TEST_F(EnergyFitCollapseCli, CollapsedCurvesPipeIntoTheTailFit) {
  const std::string e16 = *dir + "/e16.tsv", e32 = *dir + "/e32.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(16, 1) + " > " + e16).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(32, 1) + " > " + e32).exit_code, 0);
  // f(x) ~ x^-1.83 for x >> 1: local slope 1.2 + 0.63 x/(1+x), 1.824..1.829 for x in [100, 1000].
  auto r = run_command(bin("coolgas-collapse") + " " + e16 + " " + e32 + " | " + bin("coolgas-fit") +
                       " --power --t-column x --e-column y --window 100:1000 -");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string last = r.out.substr(r.out.rfind('\n', r.out.size() - 2) + 1);
  EXPECT_NEAR(std::stod(last), 1.827, 0.003) << r.out;
}

TEST_F(EnergyFitCollapseCli, EnergyRefusesRunsOfDifferentSize) {
  expect_one_error_line(run_command(bin("coolgas-energy") + " " + path(16, 1) + " " + path(32, 1)), "L = 16 vs 32");
}

TEST_F(EnergyFitCollapseCli, EveryToolGivesOneLineForEmptyInput) {
  const std::string empty = file("empty", "");
  expect_one_error_line(run_command(bin("coolgas-energy") + " " + empty), "not HDF5");
  expect_one_error_line(run_command(bin("coolgas-fit") + " --power < " + empty), "empty table");
  expect_one_error_line(run_command(bin("coolgas-collapse") + " " + empty), "empty table");
}

TEST_F(EnergyFitCollapseCli, EveryToolGivesOneLineForAFileOfTheWrongType) {
  const std::string table = file("table.tsv", "# L: 16\n# t\tE\n1\t2\n10\t1\n");
  expect_one_error_line(run_command(bin("coolgas-energy") + " " + table), "not HDF5");
  expect_one_error_line(run_command(bin("coolgas-fit") + " --power " + path(16, 1)), path(16, 1));
  expect_one_error_line(run_command(bin("coolgas-collapse") + " " + path(16, 1)), path(16, 1));
}

TEST_F(EnergyFitCollapseCli, EveryToolGivesOneLineForMissingData) {
  const std::string bare = *dir + "/bare.h5";
  { h5::Handle f = h5::open_file(bare, h5::Mode::kCreateTruncate); }
  expect_one_error_line(run_command(bin("coolgas-energy") + " " + bare), "not a coolgas trajectory: missing /parameters");
  const std::string no_E = file("no_E.tsv", "# L: 16\n# t\tT\n1\t2\n10\t1\n100\t0.5\n");
  expect_one_error_line(run_command(bin("coolgas-fit") + " --power " + no_E), "no column 'E'");
  const std::string no_L = file("no_L.tsv", "# t\tE\n1\t2\n10\t1\n");
  expect_one_error_line(run_command(bin("coolgas-collapse") + " " + no_L), "no '# L: <box side>'");
}

TEST_F(EnergyFitCollapseCli, EveryToolGivesOneLineForNaN) {
  const std::string nan_run = *dir + "/nan.h5";
  test::write_energy_run(nan_run, test::paper_parameters(16, 1), {0, 1, 2}, [](double t) { return t == 1 ? std::numeric_limits<double>::quiet_NaN() : 1.0; }, Geometry(3));
  expect_one_error_line(run_command(bin("coolgas-energy") + " " + nan_run), "not finite");
  const std::string nan_table = file("nan.tsv", "# L: 16\n# t\tE\n1\t2\n10\tnan\n100\t0.5\n");
  expect_one_error_line(run_command(bin("coolgas-fit") + " --haff " + nan_table), "not finite");
  expect_one_error_line(run_command(bin("coolgas-collapse") + " " + nan_table), "not finite");
}

TEST_F(EnergyFitCollapseCli, BadOptionsAreInputErrors) {
  expect_one_error_line(run_command(bin("coolgas-fit") + " --power --window 10:1 -  < /dev/null"), "LO must be below HI");
  expect_one_error_line(run_command(bin("coolgas-energy") + " --per-decade 0 " + path(16, 1)), "--per-decade 0");
  EXPECT_EQ(run_command(bin("coolgas-collapse") + " --help").exit_code, 0);
  // Weights from the scatter of the runs need two or more runs of every L.
  const std::string e16 = *dir + "/w16.tsv", e32 = *dir + "/w32.tsv";
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(16, 1) + " > " + e16).exit_code, 0);
  ASSERT_EQ(run_command(bin("coolgas-energy") + " " + path(32, 1) + " > " + e32).exit_code, 0);
  expect_one_error_line(run_command(bin("coolgas-collapse") + " --weights seeds " + e16 + " " + e32),
                        "--weights seeds needs two or more tables (runs) of every L; L = 16 has 1");
  expect_one_error_line(run_command(bin("coolgas-collapse") + " --weights chi2 " + e16), "--weights");
}

}  // namespace
}  // namespace coolgas
