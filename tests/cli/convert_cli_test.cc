// coolgas-convert and starts from a file, driven as a user would: a frame
// exported as extended XYZ starts a new run whose t = 0 positions and
// velocities are the source's bit for bit; ASE reads the XYZ and MDAnalysis
// the LAMMPS dump as h5py reads the trajectory (tests/cli/read_exports.py),
// for disks and rods too (each starts a run in its own dimension only);
// an H5MD file written by MDAnalysis starts a run; bad input is one line.
// A 1D file (rods) is exported as XYZ only.
#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>

#include "common/hdf5_file.h"
#include "common/random.h"
#include "common/trajectory/h5md_writer.h"
#include "tests/support/run_command.h"
#include "tests/support/simulate_cli.h"

namespace coolgas {
namespace {

using test::bin;
using test::run_command;
using test::simulate;

const char* kGas = R"([system]
N = 2000
phi = 0.2
seed = 3
[collision]
model = "inelastic"
r0 = 0.5
delta = 1e-4
[run]
t_end = 5
)";

const char* kAggregates = R"([system]
N = 3000
phi = 0.1
seed = 2
[collision]
model = "aggregation"
[run]
t_end = 20
)";

// A scene starting from `from` with the same collision model and dimension as its source.
std::string file_scene(const std::string& dir, const std::string& from, const std::string& model, int dimension) {
  return test::write_file(dir, "start.toml", "[system]\ninit = \"file\"\nfrom = \"" + from + "\"\ndimension = " +
                                                 std::to_string(dimension) + "\n[collision]\nmodel = \"" + model +
                                                 "\"\n[run]\nt_end = 1\n");
}

std::string py(const std::string& args) {
  return "/usr/bin/python3 " + test::source("tests/cli/read_exports.py") + " " + args;
}

// Row `row` (-1: the last) of a dataset, the slots with id >= 0 only when `live`.
std::vector<double> row_of(const std::string& file, const std::string& element, int row, std::size_t per, bool live) {
  h5::Handle f = h5::open_file(file, h5::Mode::kReadOnly);
  h5::Handle ds = h5::open_dataset(f.id(), element + "/value");
  const hsize_t r = row >= 0 ? hsize_t(row) : h5::shape(ds.id())[0] - 1;
  std::vector<double> v = h5::read_row<double>(ds.id(), r);
  if (!live) return v;
  h5::Handle ids = h5::open_dataset(f.id(), "particles/all/id/value");
  const std::vector<std::int32_t> id = h5::read_row<std::int32_t>(ids.id(), r);
  std::vector<double> out;
  for (std::size_t i = 0; i < id.size(); ++i)
    if (id[i] >= 0) out.insert(out.end(), v.begin() + long(per * i), v.begin() + long(per * (i + 1)));
  return out;
}

void expect_bit_identical(const std::vector<double>& a, const std::vector<double>& b, const std::string& what) {
  ASSERT_EQ(a.size(), b.size()) << what;
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0) << what << " differ";
}

struct Case {
  const char* scene;
  const char* model;
  bool aggregates;
  const char* set = "";  // --set options of the run
  int dimension = 3;     // the one they set
};

// Spheres, disks (the gas) and rods (aggregates) alike.
TEST(ConvertCli, ARunStartedFromAnExportedFrameBeginsWithItsStateBitForBit) {
  for (const Case& c : {Case{kGas, "inelastic", false}, Case{kAggregates, "aggregation", true},
                        Case{kGas, "inelastic", false, " --set system.dimension=2 --set system.phi=0.3", 2},
                        Case{kAggregates, "aggregation", true, " --set system.dimension=1", 1}}) {
    const std::string dir =
        test::scratch_dir(std::string("convert_round_trip_") + c.model + std::to_string(c.dimension));
    const std::string run = dir + "/run.h5", xyz = dir + "/last.xyz", again = dir + "/again.h5";
    ASSERT_EQ(run_command(simulate(test::write_file(dir, "run.toml", c.scene) + c.set + " -o " + run)).exit_code, 0);
    const auto e = run_command(bin("coolgas-convert") + " --last " + run + " > " + xyz);
    ASSERT_EQ(e.exit_code, 0) << e.err;
    const auto d = std::size_t(c.dimension);
    for (const std::string& from : {xyz, run}) {  // the exported frame, and the trajectory itself
      const auto s = run_command(simulate(file_scene(dir, from, c.model, c.dimension) + " --force -o " + again));
      ASSERT_EQ(s.exit_code, 0) << s.err;
      for (const char* el : {"particles/all/position", "particles/all/velocity"})
        expect_bit_identical(row_of(run, el, -1, d, c.aggregates), row_of(again, el, 0, d, false), from + " " + el);
      if (c.aggregates)
        for (const char* el : {"particles/all/diameter", "particles/all/mass"})
          expect_bit_identical(row_of(run, el, -1, 1, true), row_of(again, el, 0, 1, false), from + " " + el);
      const auto v = run_command(bin("coolgas-validate") + " " + again);
      EXPECT_EQ(v.exit_code, 0) << v.out << v.err;
    }
    // The effective scene states N, L, phi and T0: resuming needs no source file.
    std::filesystem::remove(xyz);
    const auto r = run_command(simulate("--resume " + again + " --set run.t_end=2"));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    // A frame is a start for its own dimension only.
    const int other = c.dimension == 3 ? 2 : 3;
    test::expect_simulate_refused(file_scene(dir, run, c.model, other) + " --force -o " + dir + "/other.h5",
                                  "set system.dimension = " + std::to_string(c.dimension), dir + "/other.h5");
  }
}

// Disks too: ASE reads a 2D frame as a cell (L, L, 1) periodic in the plane, z = 0.
TEST(ConvertCli, AseReadsTheXyzAndMDAnalysisTheLammpsDumpAsH5pyReadsTheRun) {
  for (const Case& c : {Case{kGas, "inelastic", false}, Case{kAggregates, "aggregation", true},
                        Case{kGas, "disks", false, " --set system.dimension=2 --set system.phi=0.3"}}) {
    const std::string dir = test::scratch_dir(std::string("convert_readers_") + c.model);
    const std::string run = dir + "/run.h5";
    ASSERT_EQ(run_command(simulate(test::write_file(dir, "run.toml", c.scene) + c.set + " -o " + run)).exit_code, 0);
    ASSERT_EQ(run_command(bin("coolgas-convert") + " " + run + " > " + dir + "/all.xyz").exit_code, 0);
    const auto a = run_command(py("xyz " + run + " " + dir + "/all.xyz"));
    EXPECT_EQ(a.exit_code, 0) << a.out << a.err;
    ASSERT_EQ(run_command(bin("coolgas-convert") + " --format lammps --last " + run + " > " + dir + "/last.dump").exit_code, 0);
    const auto m = run_command(py("lammps " + run + " " + dir + "/last.dump"));
    EXPECT_EQ(m.exit_code, 0) << m.out << m.err;
  }
}

// Rods on a ring (a 1D file from the writer; a simulated one:
// tests/cli/rod_tools_cli_test.cc):
// ASE reads each XYZ frame as a cell (L, 1, 1) periodic along x only, y = z
// = 0, positions and velocities exact; LAMMPS has no 1D mode, so a LAMMPS
// dump is refused with one line naming the XYZ alternative.
TEST(ConvertCli, ARodFileIsExportedAsXyzOnly) {
  const std::string dir = test::scratch_dir("convert_rods");
  const std::string run = dir + "/rods.h5";
  {
    RunParameters p;
    p.N = 300;
    p.L = 750.5;
    H5mdWriter w = H5mdWriter::create(run, p, true, Geometry(1));
    Random rng(81);
    std::vector<double> pos(3 * 300), vel(3 * 300);
    const std::vector<std::int32_t> img(3 * 300, 0);
    for (int f = 0; f < 3; ++f) {
      for (double& x : pos) x = p.L * rng.uniform();
      for (double& v : vel) v = rng.normal();
      w.add_frame({10.0 * f, 100 * f, 0, pos.data(), img.data(), vel.data()});
    }
  }
  ASSERT_EQ(run_command(bin("coolgas-convert") + " " + run + " > " + dir + "/all.xyz").exit_code, 0);
  const auto a = run_command(py("xyz " + run + " " + dir + "/all.xyz"));
  EXPECT_EQ(a.exit_code, 0) << a.out << a.err;
  test::expect_one_error_line(run_command(bin("coolgas-convert") + " --format lammps " + run),
                              "a 1D trajectory (rods) has no LAMMPS dump: LAMMPS runs in 2 or 3 dimensions; use "
                              "--format xyz");
}

TEST(ConvertCli, AnH5mdFileWrittenByMDAnalysisStartsARun) {
  const std::string dir = test::scratch_dir("convert_foreign_h5md");
  const std::string run = dir + "/run.h5", foreign = dir + "/mda.h5md", again = dir + "/again.h5";
  ASSERT_EQ(run_command(simulate(test::write_file(dir, "run.toml", kGas) + " -o " + run)).exit_code, 0);
  const auto w = run_command(py("h5md " + run + " " + foreign));
  ASSERT_EQ(w.exit_code, 0) << w.out << w.err;
  const auto s = run_command(bin("coolgas-simulate") + " " + file_scene(dir, foreign, "inelastic", 3) + " -o " + again);
  ASSERT_EQ(s.exit_code, 0) << s.err;
  EXPECT_NE(s.err.find("H5MD 1.1 (group 'trajectory')"), std::string::npos) << s.err;
  // MDAnalysis stores float32: the run starts from exactly those numbers.
  h5::Handle f = h5::open_file(foreign, h5::Mode::kReadOnly);
  h5::Handle ds = h5::open_dataset(f.id(), "particles/trajectory/position/value");
  expect_bit_identical(h5::read_row<double>(ds.id(), 0), row_of(again, "particles/all/position", 0, 3, false),
                       "positions");
}

// The other shape H5MD 1.1 allows: time-independent datasets, box edges a
// vector, and an absent particle (id -1, its position NaN) that is left out.
TEST(ConvertCli, AnH5mdFileOfTimeIndependentDatasetsStartsARun) {
  const std::string dir = test::scratch_dir("convert_fixed_h5md");
  const std::string run = dir + "/run.h5", foreign = dir + "/fixed.h5", again = dir + "/again.h5";
  ASSERT_EQ(run_command(simulate(test::write_file(dir, "run.toml", kGas) + " -o " + run)).exit_code, 0);
  const auto w = run_command(py("h5md_fixed " + run + " " + foreign));
  ASSERT_EQ(w.exit_code, 0) << w.out << w.err;
  const auto s = run_command(simulate(file_scene(dir, foreign, "inelastic", 3) + " -o " + again));
  ASSERT_EQ(s.exit_code, 0) << s.err;
  for (const char* el : {"particles/all/position", "particles/all/velocity"})
    expect_bit_identical(row_of(run, el, -1, 3, false), row_of(again, el, 0, 3, false), el);
}

TEST(ConvertCli, BrokenH5mdFilesAreRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("convert_bad_h5md");
  const std::string out = dir + "/out.h5";
  for (const auto& [kind, needle] : std::vector<std::pair<std::string, std::string>>{
           {"slab", "the box is not cubic (edges 10, 10, 5)"},
           {"open", "has boundary 'none'; coolgas boxes are periodic"},
           {"groups", "holds several particle groups (a, b)"}}) {
    const std::string file = dir + "/" + kind + ".h5";
    ASSERT_EQ(run_command(py("h5md_bad " + kind + " " + file)).exit_code, 0);
    test::expect_simulate_refused(file_scene(dir, file, "elastic", 3) + " -o " + out, needle, out);
  }
}

TEST(ConvertCli, BadInputIsRefusedWithOneLine) {
  const std::string dir = test::scratch_dir("convert_bad_input");
  const std::string out = dir + "/out.h5";
  const std::string box = "Lattice=\"9 0 0 0 9 0 0 0 9\" Properties=species:S:1:pos:R:3";
  std::string lattice;
  for (int i = 0; i < 216; ++i)
    lattice += "X " + std::to_string(1.5 * (i % 6) + 0.75) + " " + std::to_string(1.5 * (i / 6 % 6) + 0.75) + " " +
               std::to_string(1.5 * (i / 36) + 0.75) + "\n";
  const std::string good = test::write_file(dir, "good.xyz", "216\n" + box + "\n" + lattice);
  const std::string overlap = test::write_file(dir, "overlap.xyz", "216\n" + box + "\n" + lattice.substr(0, lattice.rfind("X ")) + "X 0.75 0.75 1.25\n");
  const std::string outside = test::write_file(dir, "outside.xyz", "216\n" + box + "\n" + lattice.substr(0, lattice.rfind("X ")) + "X 8.25 8.25 9.5\n");
  const std::string text = test::write_file(dir, "notes.txt", "a note\n");
  test::expect_simulate_refused(file_scene(dir, dir + "/missing.xyz", "elastic", 3) + " -o " + out, "no such file", out);
  test::expect_simulate_refused(file_scene(dir, overlap, "elastic", 3) + " -o " + out,
                                "particles 0 and 215 overlap: their centres are 0.5 apart, contact is at 1", out);
  test::expect_simulate_refused(file_scene(dir, outside, "elastic", 3) + " -o " + out,
                                "particle 215 is at (8.25, 8.25, 9.5), outside the box [0, 9)", out);
  test::expect_simulate_refused(file_scene(dir, good, "elastic", 3) + " --set system.L=10 -o " + out,
                                "system.L = 10 but the box of", out);
  test::expect_simulate_refused(file_scene(dir, text, "elastic", 3) + " -o " + out, "expected the number of particles", out);
  EXPECT_EQ(run_command(simulate(file_scene(dir, good, "elastic", 3) + " -o " + out)).exit_code, 0);  // the good one runs
  test::expect_one_error_line(run_command(bin("coolgas-convert") + " " + dir + "/missing.h5"), "missing.h5");
  test::expect_one_error_line(run_command(bin("coolgas-convert") + " " + text), "notes.txt");
  test::expect_one_error_line(run_command(bin("coolgas-convert") + " --format pdb " + out), "--format");
}

}  // namespace
}  // namespace coolgas
