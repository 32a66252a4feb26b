// A start from a frame of a file: the scene is completed from the file (N,
// L, phi, T0, the frame's time), positions are taken exactly, velocities
// from the file or Maxwellian at exactly T0 with zero momentum (mass-weighted
// for aggregates), and a configuration an engine cannot run on is refused
// with one line naming the pair, the position or the value.
#include "simulate/start/file_start.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>

#include "common/error.h"
#include "common/extended_xyz.h"
#include "common/hdf5_file.h"
#include "common/trajectory/h5md_writer.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// n^3 spheres on a simple cubic lattice of spacing 1.5 (no overlaps), in a box of side 1.5 n.
XyzFrame lattice(int n, bool velocities) {
  XyzFrame f;
  f.L = 1.5 * n;
  f.time = 7.5;
  for (int i = 0; i < n * n * n; ++i) {
    for (int d : {i % n, i / n % n, i / (n * n)}) f.position.push_back(1.5 * (d + 0.5));
    if (velocities)
      for (double v : {0.1 * (i % 7), -0.2, 0.3}) f.velocity.push_back(v);
  }
  return f;
}

std::string write_xyz(const std::string& dir, const XyzFrame& f) {
  std::string path = dir + "/start.xyz";
  std::ofstream out(path);
  write_xyz_frame(out, f, {});
  return path;
}

Scene file_scene(const std::string& path, const std::string& model = "elastic", const std::string& more = "") {
  return parse_scene("[system]\ninit = \"file\"\nfrom = \"" + path + "\"\n" + more + "\n[collision]\nmodel = \"" +
                         model + "\"\n[run]\nt_end = 1\n",
                     "s.toml", {});
}

std::string error_of(Scene s) {
  try {
    start_from_file(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Σ m v / Σ m and Σ m v² / (3N).
std::pair<Vec3, double> momentum_and_temperature(const Particles& p, const std::vector<double>* mass) {
  Vec3 P;
  double m_total = 0, sum = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double m = mass ? (*mass)[i] : 1.0;
    for (int d = 0; d < 3; ++d) P[d] += m * p.v[i][d];
    m_total += m;
    sum += m * dot(p.v[i], p.v[i]);
  }
  for (int d = 0; d < 3; ++d) P[d] /= m_total;
  return {P, sum / (3.0 * double(p.size()))};
}

TEST(FileStart, TheSceneIsCompletedFromTheFileAndPositionsAreExact) {
  const std::string dir = test::scratch_dir("file_start");
  const XyzFrame f = lattice(6, true);
  Scene s = file_scene(write_xyz(dir, f));
  const FileStart start = start_from_file(s);
  EXPECT_EQ(start.scene.N, 216);
  EXPECT_EQ(start.scene.L, 9.0);
  EXPECT_DOUBLE_EQ(start.scene.phi, 216 * M_PI / (6 * 729.0));
  EXPECT_EQ(start.scene.from_time, 7.5);  // the frame's own time is recorded in the effective scene
  EXPECT_EQ(start.scene.T0, Geometry(3).unit_time_temperature(216 / 729.0, start.scene.phi));  // no T0 in the file: Enskog, as for a fresh start
  ASSERT_EQ(start.particles.size(), 216u);
  for (std::size_t i = 0; i < 216; ++i)
    for (int d = 0; d < 3; ++d) {
      EXPECT_EQ(start.particles.r[i][d], f.position[3 * i + d]);
      EXPECT_EQ(start.particles.v[i][d], f.velocity[3 * i + d]);
    }
  EXPECT_FALSE(start.aggregates);
  EXPECT_NE(start.notice.find("velocities from the file"), std::string::npos) << start.notice;
  // The effective scene reads back to the same scene without the file being read.
  const Scene t = parse_scene(start.scene.to_toml(), "effective", {});
  EXPECT_EQ(t.to_toml(), start.scene.to_toml());
  EXPECT_EQ(t.T0, start.scene.T0);
}

TEST(FileStart, VelocitiesAreDrawnAtExactlyT0WithZeroMomentum) {
  const std::string dir = test::scratch_dir("file_start_draw");
  Scene s = file_scene(write_xyz(dir, lattice(6, false)), "elastic", "T0 = 0.25");
  const FileStart start = start_from_file(s);
  const auto [P, T] = momentum_and_temperature(start.particles, nullptr);
  EXPECT_NEAR(T, 0.25, 1e-14);  // rescaled to T0 exactly (system.T0 here)
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(P[d], 0, 1e-15);
}

TEST(FileStart, AggregatesKeepTheirDiametersAndMassesAndDrawMassWeightedVelocities) {
  const std::string dir = test::scratch_dir("file_start_aggregates");
  XyzFrame f = lattice(6, false);
  for (int i = 0; i < 216; ++i) {
    f.mass.push_back(1 + i % 3);
    f.diameter.push_back(std::cbrt(1 + i % 3));  // up to 1.44 < the spacing 1.5
  }
  const std::string path = write_xyz(dir, f);
  Scene s = file_scene(path, "aggregation");
  const FileStart start = start_from_file(s);
  ASSERT_TRUE(start.aggregates);
  EXPECT_EQ(start.aggregates->mass, f.mass);
  EXPECT_EQ(start.aggregates->diameter, f.diameter);
  double volume = 0;
  for (double d : f.diameter) volume += d * d * d * M_PI / 6;
  EXPECT_NEAR(start.scene.phi, volume / 729, 1e-15);
  const auto [P, T] = momentum_and_temperature(start.particles, &start.aggregates->mass);
  EXPECT_NEAR(T, start.scene.T0, 1e-14 * start.scene.T0);
  for (int d = 0; d < 3; ++d) EXPECT_NEAR(P[d], 0, 1e-15);
  // Heavier aggregates move slower: <m v^2> is the same for each mass (equipartition), to sampling error.
  double v2[3] = {0, 0, 0};
  for (int i = 0; i < 216; ++i) v2[i % 3] += f.mass[i] * dot(start.particles.v[i], start.particles.v[i]) / 72;
  for (double x : v2) EXPECT_NEAR(x / (3 * start.scene.T0), 1, 0.25);  // 72 aggregates each: 3 sigma of chi^2 with 216 dof
  // The gas models have unit spheres only.
  EXPECT_NE(error_of(file_scene(path, "inelastic", "")).find("particle 1 has diameter 1.2599"), std::string::npos)
      << error_of(file_scene(path, "inelastic"));
}

TEST(FileStart, ACoolgasTrajectoryGivesItsDumpNearestFromTimeAndItsOwnT0) {
  const std::string dir = test::scratch_dir("file_start_coolgas");
  const XyzFrame f = lattice(5, true);
  RunParameters p;
  p.N = 125;
  p.L = f.L;
  p.T0 = 0.123;
  const std::string path = dir + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, p, true, Geometry(3));
    std::vector<std::int32_t> image(3 * 125, 0);
    for (double t : {0.0, 10.0, 20.0}) {
      std::vector<double> v = f.velocity;
      v[0] = t;  // marks the dump
      w.add_frame({t, std::int64_t(t), 0, f.position.data(), image.data(), v.data()});
    }
  }
  Scene s = file_scene(path, "elastic", "from_time = 12");
  const FileStart start = start_from_file(s);
  EXPECT_EQ(start.scene.from_time, 10.0);
  EXPECT_EQ(start.particles.v[0].x, 10.0);
  EXPECT_EQ(start.scene.T0, 0.123);  // its times go on in its own unit
  EXPECT_NE(start.notice.find("T0 = 0.123 (the file's)"), std::string::npos) << start.notice;
}

TEST(FileStart, BadConfigurationsAreRefusedNamingWhatIsWrong) {
  const std::string dir = test::scratch_dir("file_start_bad");
  XyzFrame f = lattice(6, true);
  const std::string path = write_xyz(dir, f);
  EXPECT_NE(error_of(file_scene(path, "elastic", "N = 100")).find("system.N = 100 but system.from = '" + path +
                                                                  "' holds 216 particles"),
            std::string::npos);
  EXPECT_NE(error_of(file_scene(path, "elastic", "L = 10")).find("system.L = 10 but the box of"), std::string::npos);
  XyzFrame overlap = f;
  overlap.position[3 * 17] = f.position[3 * 3] + 0.3;
  overlap.position[3 * 17 + 1] = f.position[3 * 3 + 1];
  overlap.position[3 * 17 + 2] = f.position[3 * 3 + 2];
  EXPECT_NE(error_of(file_scene(write_xyz(dir, overlap))).find("particles 3 and 17 overlap: their centres are 0.3 apart"),
            std::string::npos);
  XyzFrame outside = f;
  outside.position[3 * 5 + 1] = -0.5;  // as in a box centred on the origin
  EXPECT_NE(error_of(file_scene(write_xyz(dir, outside))).find("particle 5 is at (8.25, -0.5, 0.75), outside the box [0, 9)"),
            std::string::npos) << error_of(file_scene(write_xyz(dir, outside)));
  XyzFrame small = lattice(2, true);  // in a box of side 2.5: fewer than three cells of one diameter
  small.L = 2.5;
  for (double& x : small.position) x = std::fmod(x, 2.5);
  EXPECT_NE(error_of(file_scene(write_xyz(dir, small))).find("too small"), std::string::npos)
      << error_of(file_scene(write_xyz(dir, small)));
  EXPECT_NE(error_of(file_scene(dir + "/missing.xyz")).find("no such file"), std::string::npos);
  EXPECT_NE(error_of(file_scene(dir)).find("not a regular file"), std::string::npos);
  std::ofstream(dir + "/plain.txt") << "not a configuration\n";
  EXPECT_NE(error_of(file_scene(dir + "/plain.txt")).find("expected the number of particles"), std::string::npos);
}

// Another program's H5MD file of one frame (the lattice of `f`) at time `t`.
std::string write_h5md(const std::string& dir, const XyzFrame& f, double t) {
  std::string path = dir + "/other.h5";
  h5::Handle file = h5::open_file(path, h5::Mode::kCreateTruncate);
  for (const char* g : {"h5md", "particles/all/position", "particles/all/box"}) h5::create_group(file.id(), g);
  const hsize_t n = f.position.size() / 3;
  h5::Handle value = h5::create_series(file.id(), "particles/all/position/value", h5::Type::kFloat64, {n, 3}, 1);
  h5::append_row(value.id(), h5::Type::kFloat64, f.position.data());
  h5::Handle time = h5::create_series(file.id(), "particles/all/position/time", h5::Type::kFloat64, {}, 1);
  h5::append_row(time.id(), h5::Type::kFloat64, &t);
  const double edges[3] = {f.L, f.L, f.L};
  h5::Handle box = h5::create_series(file.id(), "particles/all/box/edges", h5::Type::kFloat64, {}, 3);
  for (double e : edges) h5::append_row(box.id(), h5::Type::kFloat64, &e);
  return path;
}

// A frame's time becomes the run's start, which every --resume checks: one
// that is not finite and >= 0 is refused at the start, naming the file and
// the value, whatever the format (extended XYZ refuses it naming the line).
TEST(FileStart, AFrameTimeThatIsNotFiniteAndPositiveIsRefused) {
  const std::string dir = test::scratch_dir("file_start_time");
  const XyzFrame f = lattice(6, false);
  for (double t : {std::nan(""), std::numeric_limits<double>::infinity(), -5.0}) {
    const std::string e = error_of(file_scene(write_h5md(dir, f, t)));
    EXPECT_NE(e.find("system.from = '" + dir + "/other.h5': the frame's time t = " + format_number(t) +
                     " is not a time; times are finite and >= 0"),
              std::string::npos)
        << e;
  }
  Scene s = file_scene(write_h5md(dir, f, 2.5));
  const FileStart start = start_from_file(s);
  EXPECT_EQ(start.scene.from_time, 2.5);
}

// A file start stays below close packing, as a scene does, in every
// dimension: rods filling the ring (phi = 1) are refused in one line, and a
// hair less room than that is a start.
TEST(FileStart, ClosePackingIsRefusedAsScenesRefuseIt) {
  const std::string dir = test::scratch_dir("file_start_packed");
  for (const double L : {40.0, 40.5}) {
    XyzFrame f;
    f.dimension = 1;
    f.L = L;
    for (int i = 0; i < 40; ++i)
      for (double x : {L / 40 * (i + 0.5), 0.0, 0.0}) f.position.push_back(x);
    Scene s = file_scene(write_xyz(dir, f), "elastic", "dimension = 1");
    const std::string e = error_of(s);
    if (L == 40.0) {
      EXPECT_NE(e.find("phi = 1 is out of range: unit rods (system.dimension = 1) cover at most 1 of the ring (close "
                       "packing)"),
                std::string::npos)
          << e;
    } else {
      EXPECT_EQ(e, "");
    }
  }
}

}  // namespace
}  // namespace coolgas
