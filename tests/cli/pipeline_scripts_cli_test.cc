// The pipelines' shell helpers, run as pipelines/accuracy/Makefile runs them:
// pipelines/timed-run.sh (wall and CPU time of a run), pipelines/h5-last.sh
// (the last value of a dataset, or the last up to a time, e.g. a run's
// collision count) and
// pipelines/readme-table.sh (a pipeline's table copied into the README) and
// pipelines/verdicts.sh (the paper's claims judged on an exponent table).
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "common/trajectory/resume_frame.h"
#include "tests/support/cli_checks.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::read_text;
using test::run_command;
using test::source;

double read_number(const std::string& path) {
  std::ifstream in(path);
  double v = -1;
  in >> v;
  EXPECT_TRUE(in) << "no number in " << path;
  return v;
}

std::string timed_run(const std::string& wall_file, const std::string& command) {
  return "sh " + source("pipelines/timed-run.sh") + " " + wall_file + " " + command;
}

TEST(TimedRun, WritesTheCpuTimeOfTheCommandBesideItsWallTime) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  // One process computing: its CPU time is counted (`times` in a pipe, a
  // subshell, reads 0 here), and cannot exceed its wall time (one thread;
  // + 0.02 s for the 0.01 s resolution of both).
  const auto r = run_command(timed_run(dir + "/run.wall_s", "awk 'BEGIN { for (i = 0; i < 3e6; i++) s += i }'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double wall = read_number(dir + "/run.wall_s"), cpu = read_number(dir + "/run.cpu_s");
  EXPECT_GT(cpu, 0.0);
  EXPECT_LE(cpu, wall + 0.02);
}

TEST(TimedRun, AFailedCommandKeepsItsExitCodeAndWritesNoTimes) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const auto r = run_command(timed_run(dir + "/run.wall_s", "sh -c 'exit 5'"));
  EXPECT_EQ(r.exit_code, 5);
  EXPECT_FALSE(std::filesystem::exists(dir + "/run.wall_s"));
  EXPECT_FALSE(std::filesystem::exists(dir + "/run.cpu_s"));
}

// A run made in slices: each slice's CPU time is kept (a failed or stopped
// one too), and the run's CPU time is their sum. Two earlier slices of 1.50
// and 2.25 s are in the file; the last slice adds its own, at most its wall
// time (+ 0.02 s for the resolution of both).
TEST(TimedRun, ARunInSlicesCostsTheCpuTimeOfAllOfThem) {
  const std::string dir = test::scratch_dir("pipeline_scripts_slices");
  std::filesystem::remove(dir + "/run.cpu_s.slices");
  const auto failed = run_command(timed_run(dir + "/run.wall_s", "sh -c 'exit 3'"));
  EXPECT_EQ(failed.exit_code, 3);
  EXPECT_FALSE(std::filesystem::exists(dir + "/run.cpu_s"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/run.cpu_s.slices"));  // the stopped slice, counted
  std::ofstream(dir + "/run.cpu_s.slices") << "1.50\n2.25\n";
  const auto r = run_command(timed_run(dir + "/run.wall_s", "awk 'BEGIN { for (i = 0; i < 3e5; i++) s += i }'"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const double wall = read_number(dir + "/run.wall_s"), cpu = read_number(dir + "/run.cpu_s");
  EXPECT_GE(cpu, 3.75);
  EXPECT_LE(cpu, 3.75 + wall + 0.02);
  EXPECT_FALSE(std::filesystem::exists(dir + "/run.cpu_s.slices"));  // summed into run.cpu_s
}

TEST(H5Last, GivesTheCollisionsOfARunAtItsEnd) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const std::string scene = test::write_file(dir, "run.toml",
                                             "[system]\nL = 8\nphi = 0.208\nseed = 3\n[collision]\nmodel = \"inelastic\"\n"
                                             "r0 = 0.1\ndelta = 1e-4\n[run]\nt_end = 30\n");
  const std::string run = dir + "/run.h5";
  ASSERT_EQ(run_command(test::simulate(scene + " -o " + run)).exit_code, 0);
  const auto r = run_command("sh " + source("pipelines/h5-last.sh") + " " + run + " /observables/collisions/value");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Reference: the counter of the run's last dump (at t_end), read by the
  // trajectory library, not by h5dump.
  const ResumeFrame last = read_resume_frame(run);
  ASSERT_EQ(last.time, 30.0);
  ASSERT_GT(last.collisions, 1000);  // many rows: the last one, not the first, is read
  EXPECT_EQ(r.out, std::to_string(last.collisions) + "\n");
}

TEST(H5Last, AtATimeGivesWhatARunEndingThenCounted) {
  // Dumps do not perturb the engine, so a run to t = 10 made the collisions
  // the same scene's run to t = 30 had made by t = 10 (an exact identity).
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const std::string body = "[system]\nL = 8\nphi = 0.208\nseed = 3\n[collision]\nmodel = \"inelastic\"\n"
                           "r0 = 0.1\ndelta = 1e-4\n[run]\nt_end = ";
  for (const char* t : {"10", "30"})
    ASSERT_EQ(run_command(test::simulate(test::write_file(dir, std::string("run") + t + ".toml", body + t + "\n") +
                                         " -o " + dir + "/run" + t + ".h5"))
                  .exit_code,
              0);
  const std::string script = "sh " + source("pipelines/h5-last.sh") + " ";
  const auto at10 = run_command(script + dir + "/run30.h5 /observables/collisions/value 10");
  ASSERT_EQ(at10.exit_code, 0) << at10.err;
  const ResumeFrame short_run = read_resume_frame(dir + "/run10.h5");
  ASSERT_EQ(short_run.time, 10.0);
  ASSERT_GT(short_run.collisions, 100);
  EXPECT_EQ(at10.out, std::to_string(short_run.collisions) + "\n");
  EXPECT_NE(at10.out, run_command(script + dir + "/run30.h5 /observables/collisions/value").out);
  test::expect_one_error_line(run_command(script + dir + "/run30.h5 /observables/collisions/value -1"), "times <= -1");
  test::expect_one_error_line(run_command(script + dir + "/run30.h5 /observables/collisions/value ten"), "'ten'");
}

TEST(H5Last, AMissingFileOrDatasetIsOneErrorLine) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const std::string script = "sh " + source("pipelines/h5-last.sh") + " ";
  test::expect_one_error_line(run_command(script + dir + "/none.h5 /observables/collisions/value"), "none.h5");
  const std::string scene = test::write_file(dir, "run.toml", "[system]\nL = 6\nphi = 0.208\nseed = 1\n[run]\nt_end = 1\n");
  ASSERT_EQ(run_command(test::simulate(scene + " -o " + dir + "/run.h5")).exit_code, 0);
  test::expect_one_error_line(run_command(script + dir + "/run.h5 /observables/no_such"), "/observables/no_such");
}

TEST(ReadmeTable, ReplacesOnlyTheNamedBlock) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const std::string head = "# Title\n<!-- exponents:begin -->\nold demo\n<!-- exponents:end -->\ntext\n";
  const std::string readme = test::write_file(
      dir, "README.md", head + "<!-- exponents-workstation:begin -->\nold 1\nold 2\n<!-- exponents-workstation:end -->\ntail\n");
  const std::string table = test::write_file(dir, "exponents.md", "| a | b |\n|---|---|\n");
  const auto r = run_command("sh " + source("pipelines/readme-table.sh") + " " + table + " " + readme +
                             " exponents-workstation");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(read_text(readme),
            head + "<!-- exponents-workstation:begin -->\n| a | b |\n|---|---|\n<!-- exponents-workstation:end -->\ntail\n");
}

TEST(ReadmeTable, AReadmeWithoutTheMarkersIsOneErrorLineAndStaysAsItWas) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const std::string text = "# Title\n<!-- exponents:begin -->\nx\n<!-- exponents:end -->\n";
  const std::string readme = test::write_file(dir, "README.md", text);
  const std::string table = test::write_file(dir, "exponents.md", "| a |\n");
  test::expect_one_error_line(
      run_command("sh " + source("pipelines/readme-table.sh") + " " + table + " " + readme + " exponents-paper"),
      "exponents-paper:begin");
  EXPECT_EQ(read_text(readme), text);
}

// An exponent table (pipelines/exponents.sh's columns) of the given rows:
// quantity, measured, error, regime.
std::string exponent_table(const std::string& dir, const std::vector<std::array<std::string, 4>>& rows) {
  std::string text = "quantity\tfigure\tmeasured\terror\tpaper\tpaper_error\tdeviation\tregime\n# tool: test\n";
  for (const auto& r : rows) text += r[0] + "\t1\t" + r[1] + "\t" + r[2] + "\t-\t-\t-\t" + r[3] + "\n";
  return test::write_file(dir, "exponents.tsv", text);
}

// The verdict of the claim starting with `claim` in verdicts.sh's output.
std::string verdict_of(const std::string& table, const std::string& claim) {
  const auto r = run_command("sh " + source("pipelines/verdicts.sh") + " " + table);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);)
    if (line.rfind(claim, 0) == 0) return line.substr(line.rfind('\t') + 1);
  ADD_FAILURE() << "no claim '" << claim << "' in\n" << r.out;
  return "";
}

// The rules stated in verdicts.sh: within the tolerance supports, beyond it
// by more than 3 errors does not, between decides nothing, and evidence
// outside the paper's regime decides nothing and says why.
TEST(Verdicts, WithinToleranceBeyondItAndOutsideTheRegime) {
  const std::string dir = test::scratch_dir("pipeline_scripts");
  const auto theta = [&](const std::string& collapse, const std::string& fit, const std::string& regime) {
    return verdict_of(exponent_table(dir, {{"theta, collapse E L^(z theta) vs t/L^z", collapse, "0.01", "yes"},
                                           {"theta, power-law fit at L = 68", fit, "0.005", regime}}),
                      "theta agrees");
  };
  EXPECT_EQ(theta("1.21", "1.19", "yes").rfind("supported:", 0), 0u);
  EXPECT_EQ(theta("1.49", "1.5", "yes").rfind("not supported:", 0), 0u);
  EXPECT_EQ(theta("1.25", "1.19", "yes").rfind("not decided at this scale:", 0), 0u);
  EXPECT_EQ(theta("1.21", "1.19", "no: too late"), "not decided at this scale (theta, power-law fit at L = 68: too late)");

  const auto z = [&](const std::string& value, const std::string& error) {
    return verdict_of(exponent_table(dir, {{"z, same collapse", value, error, "yes"}}), "E(t) obeys");
  };
  EXPECT_EQ(z("2.6", "0.1").rfind("supported:", 0), 0u);
  EXPECT_EQ(z("3.5", "0.1").rfind("not supported:", 0), 0u);        // 1 beyond 0.25, 7.5 errors
  EXPECT_EQ(z("2.8", "0.1").rfind("not decided at this scale:", 0), 0u);  // 0.05 beyond: under 3 errors
  EXPECT_NE(z("2.5", "0.3").find("uncertain by more than 0.25"), std::string::npos);

  // A claim whose rows the table lacks is not decided, and says which rows.
  EXPECT_NE(verdict_of(exponent_table(dir, {}), "the kurtosis").find("no row kappa"), std::string::npos);
}

}  // namespace
}  // namespace coolgas
