// Frames of H5MD 1.1 files that other programs write, in the shapes the
// specification (nongnu.org/h5md/h5md.html, "Time-dependent data") allows
// and coolgas does not write: a scalar time step with an offset, a box that
// varies in time as a vector of edges, a length unit that is reported.
#include "common/trajectory/h5md_frame.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

// Three frames of four particles in group "gas"; frame f has positions 0.5 i + f
// and box side 10 + f; time = 10 + 2.5 f through a scalar step with offset.
std::string write_file(const std::string& name) {
  std::string path = test::scratch_dir(name) + "/other.h5";
  h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
  for (const char* g : {"h5md", "particles/gas/position", "particles/gas/box/edges"}) h5::create_group(f.id(), g);
  h5::Handle value = h5::create_series(f.id(), "particles/gas/position/value", h5::Type::kFloat64, {4, 3}, 4);
  h5::Handle edges = h5::create_series(f.id(), "particles/gas/box/edges/value", h5::Type::kFloat64, {3}, 4);
  for (int fr = 0; fr < 3; ++fr) {
    double pos[12], box[3] = {10.0 + fr, 10.0 + fr, 10.0 + fr};
    for (int i = 0; i < 12; ++i) pos[i] = 0.5 * i + fr;
    h5::append_row(value.id(), h5::Type::kFloat64, pos);
    h5::append_row(edges.id(), h5::Type::kFloat64, box);
  }
  h5::write_attr(value.id(), "unit", std::string("nm"));
  h5::Handle space(H5Screate(H5S_SCALAR));
  h5::Handle time(H5Dcreate2(f.id(), "particles/gas/position/time", H5T_IEEE_F64LE, space.id(), H5P_DEFAULT,
                             H5P_DEFAULT, H5P_DEFAULT));
  const double step = 2.5;
  H5Dwrite(time.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, &step);
  h5::write_attr(time.id(), "offset", 10.0);
  return path;
}

TEST(H5mdFrame, AScalarTimeStepAndATimeDependentBoxAreRead) {
  const std::string path = write_file("h5md_frame_scalar_time");
  const H5mdFrame last = read_h5md_frame(path, std::nullopt);
  EXPECT_EQ(last.group, "gas");
  EXPECT_EQ(last.frames, 3u);
  EXPECT_EQ(last.index, 2u);
  EXPECT_EQ(last.time, 15.0);
  EXPECT_EQ(last.L, 12.0);
  EXPECT_EQ(last.length_unit, "nm");
  EXPECT_TRUE(last.velocity.empty());
  const H5mdFrame near = read_h5md_frame(path, 12.0);  // times 10, 12.5, 15
  EXPECT_EQ(near.index, 1u);
  EXPECT_EQ(near.time, 12.5);
  EXPECT_EQ(near.L, 11.0);
  ASSERT_EQ(near.position.size(), 12u);
  for (int i = 0; i < 12; ++i) EXPECT_EQ(near.position[i], 0.5 * i + 1);
}

// A box of `dimension` d (edges: a d-vector of side 7) with two particles
// of d-component positions 1 + i d + k and velocities -(1 + i d + k).
std::string write_box_file(const std::string& name, std::int64_t d, const std::vector<double>& edges) {
  std::string path = test::scratch_dir(name) + "/flat.h5";
  h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
  for (const char* g : {"h5md", "particles/all/position", "particles/all/velocity", "particles/all/box"})
    h5::create_group(f.id(), g);
  h5::Handle box = h5::open_group(f.id(), "particles/all/box");
  h5::write_attr(box.id(), "dimension", d);
  h5::Handle e = h5::create_series(f.id(), "particles/all/box/edges", h5::Type::kFloat64, {}, 4);
  for (double x : edges) h5::append_row(e.id(), h5::Type::kFloat64, &x);
  const hsize_t k = hsize_t(std::max<std::int64_t>(d, 1));
  for (const char* el : {"position", "velocity"}) {
    h5::Handle v = h5::create_series(f.id(), std::string("particles/all/") + el + "/value", h5::Type::kFloat64,
                                     {2, k}, 4);
    std::vector<double> row(2 * k);
    for (std::size_t j = 0; j < row.size(); ++j) row[j] = (el[0] == 'p' ? 1.0 : -1.0) * double(1 + j);
    h5::append_row(v.id(), h5::Type::kFloat64, row.data());
  }
  return path;
}

std::string error_of(const std::string& path) {
  try {
    read_h5md_frame(path, std::nullopt);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Disks and rods (box/dimension 2 or 1, rows of 2 or 1 numbers) are read as
// 3-vectors with the missing components 0; a box whose dimension is not 1, 2
// or 3, or whose edges are not of that dimension or not equal, is refused.
TEST(H5mdFrame, TwoAndOneDimensionalBoxesAreRead) {
  const H5mdFrame disks = read_h5md_frame(write_box_file("h5md_frame_2d", 2, {7, 7}), std::nullopt);
  EXPECT_EQ(disks.dimension, 2);
  EXPECT_EQ(disks.L, 7.0);
  EXPECT_EQ(disks.position, (std::vector<double>{1, 2, 0, 3, 4, 0}));
  EXPECT_EQ(disks.velocity, (std::vector<double>{-1, -2, 0, -3, -4, 0}));
  const H5mdFrame rods = read_h5md_frame(write_box_file("h5md_frame_1d", 1, {7}), std::nullopt);
  EXPECT_EQ(rods.dimension, 1);
  EXPECT_EQ(rods.position, (std::vector<double>{1, 0, 0, 2, 0, 0}));
  EXPECT_EQ(rods.velocity, (std::vector<double>{-1, 0, 0, -2, 0, 0}));
  EXPECT_NE(error_of(write_box_file("h5md_frame_4d", 4, {7, 7, 7, 7})).find("has dimension 4; coolgas reads 1 (rods), 2 (disks) or 3"),
            std::string::npos);
  EXPECT_NE(error_of(write_box_file("h5md_frame_2d_edges3", 2, {7, 7, 7})).find("wrong shape (expected 2 or 2 x 2 for a box of dimension 2)"),
            std::string::npos);
  EXPECT_NE(error_of(write_box_file("h5md_frame_2d_rect", 2, {7, 8})).find("the box is not square (edges 7, 8)"),
            std::string::npos);
}

TEST(H5mdFrame, FilesThatAreNotH5mdAreRefusedNamingWhatIsMissing) {
  const std::string path = test::scratch_dir("h5md_frame_bad") + "/bare.h5";
  { h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate); }
  try {
    read_h5md_frame(path, std::nullopt);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not an H5MD file: no /h5md group"), std::string::npos) << e.what();
  }
}

// A file whose position dataset claims `dims` (chunked: nothing on disk).
std::string claiming_file(const std::string& name, const hsize_t (&dims)[3]) {
  const std::string path = test::scratch_dir(name) + "/huge.h5";
  {
    h5::Handle f = h5::open_file(path, h5::Mode::kCreateTruncate);
    for (const char* g : {"h5md", "particles/all/position", "particles/all/box"}) h5::create_group(f.id(), g);
    const hsize_t chunk[3] = {1, 4096, 3};
    h5::Handle space(H5Screate_simple(3, dims, nullptr)), dcpl(H5Pcreate(H5P_DATASET_CREATE));
    H5Pset_chunk(dcpl.id(), 3, chunk);
    h5::Handle ds(H5Dcreate2(f.id(), "particles/all/position/value", H5T_IEEE_F64LE, space.id(), H5P_DEFAULT,
                             dcpl.id(), H5P_DEFAULT));
    EXPECT_TRUE(ds.valid());
    h5::Handle edges = h5::create_series(f.id(), "particles/all/box/edges", h5::Type::kFloat64, {}, 3);
    for (double e : {10.0, 10.0, 10.0}) h5::append_row(edges.id(), h5::Type::kFloat64, &e);
  }
  return path;
}

// The one error line of reading `path`.
std::string refusal(const std::string& path, double extra_bytes_per_particle = 0) {
  try {
    read_h5md_frame(path, std::nullopt, extra_bytes_per_particle);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(read)";
}

// A frame declared 10^12 particles wide is refused naming the file and the
// dataset before its arrays are allocated, not met by "out of memory".
TEST(H5mdFrame, AFrameBeyondTheMemoryIsRefusedBeforeAllocating) {
  const std::string path = claiming_file("h5md_frame_huge", {1, 1000000000000ULL, 3});
  EXPECT_EQ(refusal(path), path + ": /particles/all/position/value of shape (1, 1000000000000, 3) holds 1e+12 "
                                  "particles; coolgas reads at most 2^31 - 1 (32-bit particle ids)");
}

// Issue 52, class 5: (5, 1e9, 3) is 24 GB a frame, within some machines'
// memory, so the frame was allocated; with what the caller needs for each
// particle besides (a start: its engine's 180 B) it is refused before.
// (10^6 B a particle here: beyond any machine's memory, so the test is the
// same everywhere.)
TEST(H5mdFrame, AFrameIsRefusedWhenItAndWhatItBecomesExceedTheMemory) {
  const std::string path = claiming_file("h5md_frame_claims", {5, 1000000000ULL, 3});
  const std::string line = refusal(path, 1e6);
  EXPECT_EQ(line.find(path + ": /particles/all/position/value of shape (5, 1000000000, 3) holds 1e+09 particles: "
                             "1 PB to read and use (1000048 B a particle); the memory available is "),
            0u)
      << line;
}

}  // namespace
}  // namespace coolgas
