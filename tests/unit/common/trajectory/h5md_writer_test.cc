// The H5MD writer (data-schema/h5md-profile.md): what it writes reads back
// exactly, a resumed file drops an interrupted burst, and real clients
// (h5py, MDAnalysis 2.4) open it.
#include "common/trajectory/h5md_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

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
  p.r0 = 0.1;
  p.delta = 1e-4;
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
    H5mdWriter w = H5mdWriter::create(path, small_params(), false);
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
  EXPECT_THROW(H5mdWriter::create(path, small_params(), false), InputError);  // no silent overwrite
}

TEST(H5mdWriter, ReopenDropsRowsAfterTheLastCompleteFrame) {
  const std::string path = test::scratch_dir("h5md_reopen") + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false);
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

TEST(H5mdWriter, H5pyAndMDAnalysisReadTheFile) {
  const std::string dir = test::scratch_dir("h5md_clients");
  const std::string path = dir + "/run.h5";
  {
    H5mdWriter w = H5mdWriter::create(path, small_params(), false);
    write_frames(w, 0, 3);
  }
  auto r = test::run_command("/usr/bin/python3 " + test::source("tests/cli/read_with_mdanalysis.py") + " " + path +
                             " 2 5 2");
  EXPECT_EQ(r.exit_code, 0) << r.out << r.err;
}

}  // namespace
}  // namespace coolgas
