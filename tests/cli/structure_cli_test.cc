// coolgas-structure and coolgas-shape run as a user would, on files written
// by the real H5MD writer: bad files, NaN and bad options give one error line,
// exit code 2 and no half table; --help states units; the tables have one
// row or block per dump; aggregation files are read as aggregates.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "common/trajectory/h5md_writer.h"
#include "common/hdf5_file.h"
#include "common/random.h"
#include "common/tsv.h"
#include "tests/support/cli_checks.h"
#include "tests/support/gas_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

using test::bin;
using test::expect_one_error_line;
using test::run_command;

const char* const kTools[] = {"coolgas-structure", "coolgas-shape"};

// A ballistic-aggregation file: 400 slots holding five aggregates of masses
// 10, 20, 50, 100 and 220 (one dump).
void write_aggregates(const std::string& path) {
  const std::int64_t n = 400;
  RunParameters p;
  p.N = n;
  p.L = 20;
  p.model = "aggregation";
  p.collision.erase("r0");  // aggregation has no restitution or cut-off (common/trajectory/collision_models.h)
  p.collision.erase("delta");
  p.seed = 4;
  H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
  std::vector<double> pos(3 * n, 0.0), vel(3 * n, 0.0), mass(n, 0.0), diameter(n, 0.0);
  std::vector<std::int32_t> img(3 * n, 0), id(n, -1);
  const double m[5] = {10, 20, 50, 100, 220};
  for (int a = 0; a < 5; ++a) {
    id[a * 50] = a * 50;
    mass[a * 50] = m[a];
    diameter[a * 50] = std::cbrt(m[a]);
    for (int d = 0; d < 3; ++d) pos[3 * a * 50 + d] = 3 + 3 * a + d, vel[3 * a * 50 + d] = 0.1 * (a - 2);
  }
  FrameView f{0.0, 0, 0, pos.data(), img.data(), vel.data()};
  f.id = id.data();
  f.mass = mass.data();
  f.diameter = diameter.data();
  w.add_frame(f);
}

class StructureCli : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir = new std::string(test::scratch_dir("structure_cli"));
    test::write_gas_file(*dir + "/run.h5");
    test::write_gas_file(*dir + "/nan.h5", true);
    write_aggregates(*dir + "/ba.h5");
    std::ofstream(*dir + "/empty.h5").close();  // an empty file
    std::ofstream(*dir + "/table.tsv") << "# t\tE\n0\t1\n";
    h5::Handle f = h5::open_file(*dir + "/no_particles.h5", h5::Mode::kCreateTruncate);
    h5::create_group(f.id(), "h5md");
  }
  static inline std::string* dir = nullptr;
  static std::string run(const std::string& tool, const std::string& args) { return bin(tool) + " " + args; }
};

TEST_F(StructureCli, EveryToolRejectsBadFilesWithOneLine) {
  for (const std::string tool : kTools) {
    SCOPED_TRACE(tool);
    expect_one_error_line(run_command(run(tool, *dir + "/empty.h5")), "cannot open");
    expect_one_error_line(run_command(run(tool, *dir + "/table.tsv")), "not HDF5");
    expect_one_error_line(run_command(run(tool, *dir + "/absent.h5")), "cannot open");
    expect_one_error_line(run_command(run(tool, *dir + "/no_particles.h5")), "missing /particles/all/position");
    expect_one_error_line(run_command(run(tool, *dir + "/nan.h5")), "particle 17");
  }
}

TEST_F(StructureCli, BadOptionsAreOneErrorLine) {
  const std::string gas = *dir + "/run.h5";
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --grid 7")), "--grid");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --grid 2000")), "--grid");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --peak-fraction 1.5")), "--peak-fraction");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --direct-shells 9")), "--direct-shells");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --series --correlation")), "exclude");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --correlation")), "exclude");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --r-max 3")), "--rdf");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --r-max 13")), "L/2 = 12.5");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --r-max 1.05")), "raise --r-max");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --r-max -1")), "--r-max");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --bins-per-sigma 0")), "--bins-per-sigma");
  expect_one_error_line(run_command(run("coolgas-structure", gas + " --rdf --contact-bins 1")), "--contact-bins");
  expect_one_error_line(run_command(run("coolgas-structure", *dir + "/ba.h5 --rdf")), "ballistic-aggregation");
  expect_one_error_line(run_command(run("coolgas-shape", gas + " --bins-per-decade 0")), "--bins-per-decade");
  expect_one_error_line(run_command(run("coolgas-shape", gas + " --fit-mass ten:")), "--fit-mass");
  expect_one_error_line(run_command(run("coolgas-shape", gas + " --min-mass 0")), "--min-mass");
  expect_one_error_line(run_command(run("coolgas-shape", gas + " --series --clusters")), "exclude");
}

TEST_F(StructureCli, HelpStatesUnits) {
  for (const std::string tool : kTools) {
    const auto r = run_command(bin(tool) + " --help");
    EXPECT_EQ(r.exit_code, 0) << tool;
    EXPECT_NE(r.out.find("[1/omega0]"), std::string::npos) << tool;
    EXPECT_NE(r.out.find("[sigma]"), std::string::npos) << tool;
  }
}

Table table_of(const std::string& command) {
  const auto r = run_command(command);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  std::istringstream in(r.out);
  return read_table(in, command);
}

// Uniform random points: one series row per dump, and S within a few errors of 1.
TEST_F(StructureCli, TablesHaveARowOrBlockPerDump) {
  const Table series = table_of(run("coolgas-structure", "--series " + *dir + "/run.h5"));
  EXPECT_EQ(series.rows.size(), 2u);
  EXPECT_EQ(series.columns, (std::vector<std::string>{"t", "L_t", "k_mean", "k_cut", "k_peak", "S_peak", "L_C", "L_v"}));
  const Table s = table_of(run("coolgas-structure", "--time 10 " + *dir + "/run.h5"));
  ASSERT_EQ(s.rows.size(), 6u);  // shells 1 .. 24/4
  for (const auto& row : s.rows) EXPECT_NEAR(row[s.column("S")], 1, 5 * row[s.column("S_err")]);
  const Table c = table_of(run("coolgas-structure", "--correlation --time 0 " + *dir + "/run.h5"));
  EXPECT_EQ(c.rows.front()[c.column("C")], 1);
  const Table shape = table_of(run("coolgas-shape", "--series " + *dir + "/run.h5"));
  EXPECT_EQ(shape.rows.size(), 2u);
}

// g(r) of uniform random points: blocks of r in bins of sigma/50 up to 5 sigma
// by default, flat at 1 (each bin within 5 errors); the series has one row
// per dump, g(sigma+) near 1 beside the Carnahan-Starling value of the file's phi.
TEST_F(StructureCli, RadialDistributionOfAnIdealGasIsFlat) {
  const Table g = table_of(run("coolgas-structure", "--rdf --time 10 " + *dir + "/run.h5"));
  EXPECT_EQ(g.columns, (std::vector<std::string>{"t", "r", "g", "g_err", "pairs"}));
  ASSERT_EQ(g.rows.size(), 250u);
  EXPECT_DOUBLE_EQ(g.rows.back()[g.column("r")], 4.99);
  for (const auto& row : g.rows)
    if (row[g.column("r")] > 1) EXPECT_NEAR(row[g.column("g")], 1, 5 * row[g.column("g_err")]);
  const Table series = table_of(run("coolgas-structure", "--rdf --series --bins-per-sigma 20 --contact-bins 4 " + *dir + "/run.h5"));
  EXPECT_EQ(series.columns,
            (std::vector<std::string>{"t", "g_contact", "g_contact_err", "kappa", "contact_pairs", "g_equilibrium"}));
  ASSERT_EQ(series.rows.size(), 2u);
  const double phi = 3000 * M_PI / (6 * 25.0 * 25 * 25);
  for (const auto& row : series.rows) {
    EXPECT_NEAR(row[series.column("g_contact")], 1, 4 * row[series.column("g_contact_err")]);
    EXPECT_DOUBLE_EQ(row[series.column("g_equilibrium")], (1 - phi / 2) / std::pow(1 - phi, 3));
  }
  EXPECT_NE(series.get("contact")->find("4 bins above sigma"), std::string::npos);
}

// Aggregates are the density's points, weighted by mass, and the shape
// tool's solid spheres: d_f = 3 exactly.
TEST_F(StructureCli, AggregationFilesAreReadAsAggregates) {
  const Table s = table_of(run("coolgas-structure", *dir + "/ba.h5"));
  EXPECT_NE(s.get("density")->find("aggregates weighted by their mass"), std::string::npos);
  const Table shape = table_of(run("coolgas-shape", "--series " + *dir + "/ba.h5"));
  ASSERT_EQ(shape.rows.size(), 1u);
  EXPECT_NEAR(shape.rows[0][shape.column("d_f")], 3, 1e-9);
  EXPECT_EQ(shape.rows[0][shape.column("fit_bins")], 5);
}

}  // namespace
}  // namespace coolgas
