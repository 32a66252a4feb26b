// The H5MD writer (data-schema/h5md-profile.md): what it writes reads back
// exactly, a resumed file drops an interrupted burst, and real clients
// (h5py, MDAnalysis 2.4) open it.
#include "common/trajectory/h5md_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vector>

#include "common/error.h"
#include "common/hdf5_file.h"
#include "tests/support/run_command.h"

namespace coolgas {
namespace {

RunParameters small_params() {
  RunParameters p;
  p.scene_toml = "[system]\nN = 2\n";
  p.seed = 7;
  p.N = 2;
  p.L = 5;
  p.phi = 2 * 3.141592653589793 / 6 / 125;
  p.T0 = 0.5;
  p.model = "inelastic";
  p.collision["r0"] = 0.1;
  p.collision["delta"] = 1e-4;
  return p;
}

void write_frames(H5mdWriter& w, int first, int count) {
  for (int f = first; f < first + count; ++f) {
    const double pos[6] = {0.5, 1.5, 2.5, 3.0 + f, 4.0, 0.25};
    const std::int32_t img[6] = {0, 0, 0, f, -1, 2};
    const double vel[6] = {0.1 * f, 0.2, -0.3, -0.1 * f, -0.2, 0.3};
    w.add_observables({double(f), 10 * f, f, 0.5 * f, {0, 0, 0}});
    w.add_frame({double(f), 10 * f, f, pos, img, vel});
  }
}

TEST(H5mdWriter, FramesReadBackExactly) {
  const std::string path = test::scratch_dir("h5md_roundtrip") + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false, Geometry(3));
    write_frames(w, 0, 3);
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle pos = h5::open_dataset(f.id(), "particles/all/position/value");
  EXPECT_EQ(h5::shape(pos.id()), (std::vector<hsize_t>{3, 2, 3}));
  EXPECT_EQ(h5::read_row<double>(pos.id(), 2)[3], 5.0);
  h5::Handle img = h5::open_dataset(f.id(), "particles/all/image/value");
  EXPECT_EQ(h5::read_row<std::int32_t>(img.id(), 1)[4], -1);
  h5::Handle par = h5::open_group(f.id(), "parameters");
  EXPECT_EQ(h5::read_attr_string(par.id(), "model"), "inelastic");
  EXPECT_EQ(h5::read_attr_int(par.id(), "seed"), 7);
  EXPECT_THROW(H5mdWriter::create(path, small_params(), false, Geometry(3)), InputError);  // no silent overwrite
}

TEST(H5mdWriter, ReopenDropsRowsAfterTheLastCompleteFrame) {
  const std::string path = test::scratch_dir("h5md_reopen") + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false, Geometry(3));
    write_frames(w, 0, 2);
    w.add_observables({1.5, 15, 1, 0.75, {0, 0, 0}});
    w.flush();  // an observable row after the last frame, as a killed run may leave
  }
  {
    H5mdWriter w = H5mdWriter::reopen(path);
    write_frames(w, 2, 1);
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  h5::Handle t = h5::open_dataset(f.id(), "observables/kinetic_energy/time");
  EXPECT_EQ(h5::read_all<double>(t.id()), (std::vector<double>{0, 1, 2}));
}

// A new scene is written into a copy that takes the file's place whole: the
// scene changes, the frames stay, the file still appends in SWMR mode, and
// no copy is left beside it.
TEST(H5mdWriter, ReopenWithANewSceneReplacesItThroughAWholeCopy) {
  const std::string path = test::scratch_dir("h5md_reopen_scene") + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false, Geometry(3));
    write_frames(w, 0, 2);
  }
  const std::string scene = "[system]\nN = 2\n[run]\nt_end = 50\n";
  {
    H5mdWriter w = H5mdWriter::reopen(path, &scene);
    write_frames(w, 2, 1);
  }
  EXPECT_FALSE(std::filesystem::exists(path + ".partial"));
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  EXPECT_EQ(h5::read_attr_string(h5::open_group(f.id(), "parameters").id(), "scene"), scene);
  EXPECT_TRUE(h5::appends_in_swmr(f));
  h5::Handle t = h5::open_dataset(f.id(), "particles/all/position/time");
  EXPECT_EQ(h5::read_all<double>(t.id()), (std::vector<double>{0, 1, 2}));
}

// The filters and chunk shape a dataset was created with.
struct StoredAs {
  std::vector<H5Z_filter_t> filters;
  std::vector<hsize_t> chunk;
};
StoredAs stored_as(hid_t file, const std::string& path) {
  h5::Handle ds = h5::open_dataset(file, path);
  h5::Handle dcpl(H5Dget_create_plist(ds.id()));
  StoredAs s;
  for (int i = 0; i < H5Pget_nfilters(dcpl.id()); ++i) {
    unsigned flags = 0;
    std::size_t n_values = 0;
    s.filters.push_back(H5Pget_filter2(dcpl.id(), unsigned(i), &flags, &n_values, nullptr, 0, nullptr, nullptr));
  }
  s.chunk.resize(std::size_t(H5Pget_chunk(dcpl.id(), 0, nullptr)));
  H5Pget_chunk(dcpl.id(), int(s.chunk.size()), s.chunk.data());
  return s;
}

// N = 10 particles in chunks of 4: three chunks per dump, the last one
// partial. Every number must come back bit for bit (the filters are lossless),
// and the per-particle series carry shuffle then deflate, the others nothing.
TEST(H5mdWriter, DumpsAreChunkedAndCompressedLosslessly) {
  const std::string path = test::scratch_dir("h5md_compressed") + "/run.h5";
  RunParameters p = small_params();
  p.N = 10;
  p.L = 10;
  std::vector<double> pos(30), vel(30);
  std::vector<std::int32_t> img(30);
  for (int i = 0; i < 30; ++i) {
    pos[std::size_t(i)] = std::nextafter(10.0 * i / 30.0, 0.0);  // every mantissa bit in use
    vel[std::size_t(i)] = -1e-7 * (i + 1) / 3.0;
    img[std::size_t(i)] = i % 7 - 3;
  }
  {
    H5mdWriter w = H5mdWriter::create(path, p, false, Geometry(3), {.particles_per_chunk = 4, .deflate_level = 1});
    for (int f = 0; f < 2; ++f) w.add_frame({double(f), f, 0, pos.data(), img.data(), vel.data()});
  }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  const std::vector<H5Z_filter_t> shuffle_deflate{H5Z_FILTER_SHUFFLE, H5Z_FILTER_DEFLATE};
  for (const char* name : {"position", "velocity", "image"}) {
    const StoredAs s = stored_as(f.id(), std::string("particles/all/") + name + "/value");
    EXPECT_EQ(s.filters, shuffle_deflate) << name;
    EXPECT_EQ(s.chunk, (std::vector<hsize_t>{1, 4, 3})) << name;
  }
  EXPECT_TRUE(stored_as(f.id(), "particles/all/box/edges/value").filters.empty());
  EXPECT_TRUE(stored_as(f.id(), "particles/all/position/time").filters.empty());
  EXPECT_EQ(h5::read_row<double>(h5::open_dataset(f.id(), "particles/all/position/value").id(), 1), pos);
  EXPECT_EQ(h5::read_row<double>(h5::open_dataset(f.id(), "particles/all/velocity/value").id(), 1), vel);
  EXPECT_EQ(h5::read_row<std::int32_t>(h5::open_dataset(f.id(), "particles/all/image/value").id(), 0), img);
}

// Fewer particles than a chunk holds: the chunk is cut to N (HDF5 refuses a
// chunk larger than a fixed dimension).
TEST(H5mdWriter, AChunkNeverExceedsTheParticles) {
  const std::string path = test::scratch_dir("h5md_small_chunk") + "/run.h5";
  { H5mdWriter w = H5mdWriter::create(path, small_params(), false, Geometry(3)); }
  h5::Handle f = h5::open_file(path, h5::Mode::kReadOnly);
  EXPECT_EQ(stored_as(f.id(), "particles/all/position/value").chunk, (std::vector<hsize_t>{1, 2, 3}));
}

TEST(H5mdWriter, H5pyAndMDAnalysisReadTheFile) {
  const std::string dir = test::scratch_dir("h5md_clients");
  const std::string path = dir + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false, Geometry(3));
    write_frames(w, 0, 3);
  }
  auto r = test::run_command("/usr/bin/python3 " + test::source("tests/cli/read_with_mdanalysis.py") + " " + path +
                             " 2 5 2");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace coolgas
