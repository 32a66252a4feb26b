// The cost model (simulate/run/run_eta.h), judged by its accuracy on
// finished runs rather than by the values of its constants: the cumulative
// collisions C(t) of 15 inelastic gases and 2 ballistic aggregations of the
// workstation study (tests/data/eta, written by tests/bench/eta_curves.py:
// the paper's gas at L = 34 to 136 up to t = 5e5, phi = 0.052 to 0.208,
// r0 = 0.1 to 0.9, delta = 1e-3 to 1e-5) replayed row by row
// (tests/support/eta_replay.h), each as it ended and as if it had ended at
// t = 1e3, 1e4, ...
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "simulate/run/models.h"
#include "simulate/run/run_eta.h"
#include "tests/support/eta_replay.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

struct Curve {
  std::string name;
  RunParameters params;
  std::vector<double> time, collisions;
};

// "# model=inelastic N=124908 L=68.0 phi=0.208 r0=0.1 delta=0.0001" then t and C rows.
Curve read_curve(const std::filesystem::path& path) {
  Curve c;
  c.name = path.stem().string();
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("# model=", 0) == 0) {
      std::istringstream words(line.substr(2));
      for (std::string w; words >> w;) {
        const std::string key = w.substr(0, w.find('=')), value = w.substr(w.find('=') + 1);
        if (key == "model") c.params.model = value;
        if (key == "N") c.params.N = std::stoll(value);
        if (key == "L") c.params.L = std::stod(value);
        if (key == "phi") c.params.phi = std::stod(value);
        if (key == "r0") c.params.collision["r0"] = std::stod(value);
        if (key == "delta") c.params.collision["delta"] = std::stod(value);
      }
    } else if (!line.empty() && line[0] != '#' && line[0] != 't') {
      std::istringstream row(line);
      double t = 0, n = 0;
      row >> t >> n;
      c.time.push_back(t);
      c.collisions.push_back(n);
    }
  }
  return c;
}

std::vector<Curve> curves() {
  std::vector<Curve> all;
  for (const auto& entry : std::filesystem::directory_iterator(test::source("tests/data/eta")))
    if (entry.path().extension() == ".tsv") all.push_back(read_curve(entry.path()));
  return all;
}

TEST(RunEtaReplay, TheCurvesAreThere) {
  const std::vector<Curve> all = curves();
  ASSERT_EQ(all.size(), 17u);
  for (const Curve& c : all) EXPECT_GT(c.time.size(), 50u) << c.name;
}

// Between 10 % and 90 % of each run, the collisions expected still over
// those really left: within a factor 2 throughout in at least three
// quarters of the (run, end) cases, and within a factor 3.5 in every one
// (the figures of today's rule: tests/bench/README.md).
TEST(RunEtaReplay, TheTimeLeftIsRightWithinAFactorTwoOnMostRuns) {
  int cases = 0, within_two = 0;
  for (const Curve& c : curves())
    for (std::size_t end : test::replay_ends(c.time)) {
      const test::EtaReplay r = test::replay_eta(c.time, c.collisions, end, c.params);
      if (!(r.hi > 0)) continue;  // a run too short to be extrapolated
      ++cases;
      within_two += r.lo >= 0.5 && r.hi <= 2;
      EXPECT_GE(r.lo, 1 / 3.5) << c.name << " to t = " << c.time[end] << " at t = " << r.t_lo;
      EXPECT_LE(r.hi, 3.5) << c.name << " to t = " << c.time[end] << " at t = " << r.t_hi;
    }
  EXPECT_GT(cases, 40);
  EXPECT_GE(within_two, 0.75 * cases) << within_two << " of " << cases;
}

// The plan of a run (simulate/run/run_plan.h) extrapolates from t = 100:
// fed each run's C(t) up to t = 100 only, the rule's C(t_end) is within a
// factor 2.5 of the run's.
TEST(RunEtaReplay, ThePlanFromTheFirstHundredTimeUnitsIsRightWithinAFactor2p5) {
  for (const Curve& c : curves()) {
    RunEta eta = run_eta_for(c.params, Geometry(3));
    for (std::size_t i = 0; i < c.time.size() && c.time[i] <= 100; ++i) eta.add({c.time[i], c.collisions[i], 0});
    const double ratio = eta.expected_collisions(c.time.back()) / c.collisions.back();
    EXPECT_GT(ratio, 1 / 2.5) << c.name;
    EXPECT_LT(ratio, 2.5) << c.name;
  }
}

}  // namespace
}  // namespace coolgas
