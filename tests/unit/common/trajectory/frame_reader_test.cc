// The dump reader on files from the real H5MD writer: frames read back
// exactly, dump times and the nearest dump, the provenance of the run,
// and the errors for files that are not trajectories.
#include "common/trajectory/frame_reader.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.h"
#include "common/trajectory/h5md_writer.h"
#include "common/hdf5_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

constexpr int kN = 4;

std::string write_run(const std::string& name, int frames) {
  std::string path = test::scratch_dir(name) + "/run.h5";
  RunParameters p;
  p.N = kN;
  p.L = 7.5;
  p.seed = 42;
  p.phi = 0.01;
  p.model = "inelastic";
  p.collision["r0"] = 0.1;
  p.collision["delta"] = 1e-4;
  H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(3));
  for (int f = 0; f < frames; ++f) {
    double pos[3 * kN], vel[3 * kN];
    std::int32_t img[3 * kN];
    for (int i = 0; i < 3 * kN; ++i) {
      pos[i] = 0.5 * i + 0.01 * f;
      vel[i] = -1.0 * i * (f + 1);
      img[i] = i - f;
    }
    w.add_frame({f * 10.0, 100 * f, 0, pos, img, vel});
  }
  return path;
}

TEST(Trajectory, FramesReadBackExactly) {
  const std::string path = write_run("frame_reader_exact", 3);
  Trajectory traj(path, kPosition | kVelocity | kImage);
  EXPECT_EQ(traj.particles(), kN);
  EXPECT_EQ(traj.dump_times(), (std::vector<double>{0, 10, 20}));
  Frame f;
  traj.read(2, f);
  EXPECT_EQ(f.time, 20);
  EXPECT_EQ(f.step, 200);
  EXPECT_EQ(f.L, 7.5);
  ASSERT_EQ(f.position.size(), 3u * kN);
  EXPECT_EQ(f.position[5], 2.5 + 0.02);
  EXPECT_EQ(f.velocity[5], -15.0);
  EXPECT_EQ(f.image[5], 3);
  EXPECT_THROW(traj.read(3, f), InputError);
}

TEST(Trajectory, NearestDumpAndSelection) {
  Trajectory traj(write_run("frame_reader_nearest", 3), kPosition);
  EXPECT_EQ(traj.nearest_dump(-5), 0u);
  EXPECT_EQ(traj.nearest_dump(14), 1u);
  EXPECT_EQ(traj.nearest_dump(15), 1u);  // a tie goes to the earlier dump
  EXPECT_EQ(traj.nearest_dump(1e9), 2u);
  EXPECT_EQ(traj.dumps_nearest({}), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(traj.dumps_nearest({19, 1}), (std::vector<std::size_t>{2, 0}));
}

TEST(Trajectory, ProvenanceCarriesTheRunParameters) {
  const std::string path = write_run("frame_reader_provenance", 1);
  const Provenance p = Trajectory(path, kPosition).provenance();
  auto get = [&](const std::string& key) {
    for (const auto& [k, v] : p)
      if (k == key) return v;
    return std::string("(absent)");
  };
  EXPECT_EQ(get("input"), path);
  EXPECT_EQ(get("N"), "4");
  EXPECT_EQ(get("L"), "7.5");
  EXPECT_EQ(get("seed"), "42");
  EXPECT_EQ(get("model"), "inelastic");
  EXPECT_EQ(get("r0"), "0.1");
}

// A crash between the particle rows and the /restart row of a burst leaves a
// frame without its restart row: it is not a complete dump and is not listed.
TEST(Trajectory, IgnoresAFrameWhoseBurstWasInterrupted) {
  const std::string path = write_run("frame_reader_interrupted", 2);
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kReadWrite);
    h5::Handle t = h5::open_dataset(f.id(), "particles/all/position/time");
    h5::Handle s = h5::open_dataset(f.id(), "particles/all/position/step");
    h5::Handle v = h5::open_dataset(f.id(), "particles/all/position/value");
    const double time = 30, pos[3 * kN] = {};
    const std::int64_t step = 300;
    h5::append_row(t.id(), h5::Type::kFloat64, &time);
    h5::append_row(s.id(), h5::Type::kInt64, &step);
    h5::append_row(v.id(), h5::Type::kFloat64, pos);
  }
  EXPECT_EQ(Trajectory(path, kPosition).dump_times(), (std::vector<double>{0, 10}));
}

// A 1D file (rods on a ring: one number per vector, box edges (F, 1, 1)):
// a reader that opts in with kAnyDimension gets x with y = z = 0 and the
// ring's length as L, its provenance says '# dimension: 1'; any other
// reader is refused with a line naming the dimension.
TEST(Trajectory, ReadsA1DFileWidenedWithZerosWhenAsked) {
  const std::string path = test::scratch_dir("frame_reader_1d") + "/rods.h5";
  {
    RunParameters p;
    p.N = kN;
    p.L = 12;
    H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(1));
    double pos[3 * kN], vel[3 * kN];
    std::int32_t img[3 * kN];
    for (int i = 0; i < 3 * kN; ++i) pos[i] = 0.25 * i, vel[i] = -i, img[i] = i;
    w.add_frame({3.0, 7, 0, pos, img, vel});
  }
  const Trajectory traj(path, kPosition | kVelocity | kImage | kAnyDimension);
  EXPECT_EQ(traj.dimension(), 1);
  Frame f;
  traj.read(0, f);
  EXPECT_EQ(f.L, 12);
  ASSERT_EQ(f.position.size(), 3u * kN);
  for (int i = 0; i < kN; ++i) {  // the writer keeps component 0 of each 3-vector
    EXPECT_EQ(f.position[3 * i], 0.25 * (3 * i));
    EXPECT_EQ(f.velocity[3 * i], -(3 * i));
    EXPECT_EQ(f.image[3 * i], 3 * i);
    for (int k = 1; k < 3; ++k) EXPECT_EQ(f.position[3 * i + k], 0) << i << " " << k;
    for (int k = 1; k < 3; ++k) EXPECT_EQ(f.velocity[3 * i + k], 0) << i << " " << k;
  }
  const Provenance p = traj.provenance();
  EXPECT_NE(std::find(p.begin(), p.end(), std::pair<std::string, std::string>{"dimension", "1"}), p.end());
  try {
    Trajectory refused(path, kPosition);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("a 1D trajectory (box/dimension = 1)"), std::string::npos) << e.what();
  }
}

TEST(Trajectory, NamesTheFileAndTheMissingDataset) {
  const std::string path = test::scratch_dir("frame_reader_missing") + "/RUN.h5";
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    h5::create_group(f.id(), "particles/all/velocity");
  }
  try {
    Trajectory traj(path, kPosition);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), path + ": not a coolgas trajectory: missing /particles/all/position/value");
  }
  EXPECT_THROW(Trajectory(write_run("frame_reader_no_dumps", 0), kVelocity), InputError);  // holds no dumps
}

}  // namespace
}  // namespace coolgas
